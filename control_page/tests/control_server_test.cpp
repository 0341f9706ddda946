// A real server on loopback, asked with cpp-httplib's client as a browser or script would.
#include "control_page/control_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "base/socket.hpp"
#include "control_page/access_token.hpp"
#include "image/png_io.hpp"
#include "scaled_picture.hpp"

namespace l2 {
namespace {

constexpr const char* kToken = "0123456789abcdef0123456789abcdef";

HttpAddress any_port(const std::string& host = "127.0.0.1") {
  HttpAddress a;
  a.host = host;
  return a;
}

RgbImage gradient(int w, int h) {
  RgbImage p(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      p.set(x, y, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 200});
  return p;
}

RgbImage decode(const std::string& png) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("control-page-" + std::to_string(getpid()) + ".png");
  std::ofstream(file, std::ios::binary) << png;
  RgbImage p = read_png(file);
  std::filesystem::remove(file);
  return p;
}

TEST(ControlServer, ServesThePageItsStateAndTheDisplays) {
  ControlServer server(any_port(), kToken);
  EXPECT_EQ(server.url(),
            "http://127.0.0.1:" + std::to_string(server.port()) + "/?token=" + kToken);
  RunState s;
  s.wall_name = "test wall";
  s.frame = 7;
  server.publish(s);
  auto shown = std::make_shared<std::vector<RgbImage>>();
  shown->push_back(gradient(100, 60));
  server.publish_displays(shown);

  httplib::Client client("127.0.0.1", server.port());
  const auto page = client.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<script src=\"/app.js\">"), std::string::npos);
  const auto script = client.Get("/app.js");
  ASSERT_TRUE(script);
  EXPECT_NE(script->body.find("/api/state"), std::string::npos);

  const auto state = client.Get("/api/state");  // on loopback, reading needs no token
  ASSERT_TRUE(state);
  const auto j = nlohmann::json::parse(state->body);
  EXPECT_EQ(j["wall"]["name"], "test wall");
  EXPECT_EQ(j["frame"], 7);

  const auto full = client.Get("/api/display/0.png");
  ASSERT_TRUE(full);
  ASSERT_EQ(full->status, 200);
  EXPECT_EQ(full->get_header_value("Content-Type"), "image/png");
  EXPECT_TRUE(decode(full->body) == shown->front());

  const auto small = client.Get("/api/display/0.png?scale=4");
  ASSERT_TRUE(small);
  const RgbImage p = decode(small->body);
  ASSERT_EQ(p.width(), 25);
  ASSERT_EQ(p.height(), 15);
  EXPECT_EQ(p.at(3, 2), (Rgb{12, 8, 200}));  // pixel (12, 8) of the display

  const auto missing = client.Get("/api/display/1.png");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(client.Get("/api/display/0.png?scale=0")->status, 400);
}

TEST(ControlServer, IsWatchedOnlyWhileAPageReadsItsState) {
  ControlServer server(any_port(), kToken);
  server.publish(RunState{});
  EXPECT_FALSE(server.watched(std::chrono::hours(1)));  // nobody has asked yet
  httplib::Client client("127.0.0.1", server.port());
  ASSERT_TRUE(client.Get("/app.js"));
  EXPECT_FALSE(server.watched(std::chrono::hours(1)));  // the page, not yet its state
  ASSERT_TRUE(client.Get("/api/state"));
  EXPECT_TRUE(server.watched(std::chrono::hours(1)));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(server.watched(std::chrono::milliseconds(10)));  // the reader went away
}

// Stands for the run: takes the requests between its "frames" and decides each, pausing
// always and refusing every balance mode but kd.
class FakeRun {
 public:
  explicit FakeRun(ControlServer& server)
      : thread_([this, &server] {
          while (!done_) {
            for (const ControlRequest& r : server.inbox().take()) {
              taken_.push_back(r);
              server.inbox().decide(r.ticket, decide(r));
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
        }) {}
  // Every request it took, oldest first.
  std::vector<ControlRequest> end() {
    done_ = true;
    thread_.join();
    return taken_;
  }

 private:
  static ControlDecision decide(const ControlRequest& r) {
    if (r.action != ControlAction::Balance) return {200, "paused"};
    if (r.argument == "kd") return {200, "balance mode: kd"};
    return {400, "balance mode '" + r.argument + "': expected \"kd\""};
  }

  std::atomic<bool> done_ = false;
  std::vector<ControlRequest> taken_;
  std::thread thread_;
};

TEST(ControlServer, SteeringNeedsTheTokenAndARefusalChangesNothing) {
  ControlServer server(any_port(), kToken);
  httplib::Client client("127.0.0.1", server.port());
  const auto bare = client.Post("/api/pause");
  ASSERT_TRUE(bare);
  EXPECT_EQ(bare->status, 403);
  EXPECT_EQ(bare->body, R"({"error":"this needs the run's token"})");
  const auto wrong = client.Post("/api/stop?token=0123456789abcdef0123456789abcdee");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 403);
  EXPECT_TRUE(server.inbox().take().empty());

  FakeRun run(server);
  const auto paused = client.Post(std::string("/api/pause?token=") + kToken);
  EXPECT_EQ(paused->status, 200);
  EXPECT_EQ(paused->body, R"({"done":"paused"})");
  const httplib::Headers header{{"X-L2-Token", kToken}};
  EXPECT_EQ(client.Post("/api/balance?mode=kd", header, "", "text/plain")->status, 200);
  EXPECT_EQ(client.Post("/api/balance", header, "", "text/plain")->status, 400);
  const std::vector<ControlRequest> got = run.end();
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].action, ControlAction::Pause);
  EXPECT_EQ(got[1].action, ControlAction::Balance);
  EXPECT_EQ(got[1].argument, "kd");
}

// `curl -X POST URL` sends no body and says nothing of one (no Content-Length, no chunks):
// cpp-httplib read on for a body until its read timed out and answered 400. Sent here as curl
// sends it, on a socket of the test's own.
TEST(ControlServer, APostWithoutALengthIsSteering) {
  ControlServer server(any_port(), kToken);
  FakeRun run(server);
  const Fd peer =
      connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port()), std::chrono::seconds(10));
  const std::string request = std::string("POST /api/pause?token=") + kToken +
                              " HTTP/1.1\r\nHost: 127.0.0.1\r\nUser-Agent: curl/7.88.1\r\n"
                              "Accept: */*\r\n\r\n";
  const iovec part{const_cast<char*>(request.data()), request.size()};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  send_all(peer.get(), {&part, 1}, deadline, "the control page");
  // The answer, read until its body has come (or the server closes, or the deadline passes).
  std::string answer;
  while (answer.find(R"({"done":"paused"})") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    char buffer[4096];
    const ssize_t n = ::recv(peer.get(), buffer, sizeof buffer, 0);
    if (n == 0) break;
    if (n > 0) answer.append(buffer, static_cast<std::size_t>(n));
    if (n < 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(answer.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << answer;
  EXPECT_NE(answer.find(R"({"done":"paused"})"), std::string::npos) << answer;
  const std::vector<ControlRequest> got = run.end();
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].action, ControlAction::Pause);
}

// The answer is the run's decision: a refusal with its status and reason, JSON-quoted.
TEST(ControlServer, ARequestIsAnsweredWithTheRunsDecision) {
  ControlServer server(any_port(), kToken);
  httplib::Client client("127.0.0.1", server.port());
  FakeRun run(server);
  const auto refused = client.Post(std::string("/api/balance?mode=sideways&token=") + kToken);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);
  EXPECT_EQ(refused->body, R"({"error":"balance mode 'sideways': expected \"kd\""})");
  EXPECT_EQ(run.end().size(), 1u);
}

// A run that takes no request (starting, or held up) gets none: the request is withdrawn.
TEST(ControlServer, ARequestNotTakenIsWithdrawnWith503) {
  ControlServer server(any_port(), kToken, std::chrono::milliseconds(50));
  httplib::Client client("127.0.0.1", server.port());
  const auto r = client.Post(std::string("/api/pause?token=") + kToken);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_EQ(r->body,
            R"({"error":"the run took no request within 0.05 s (it is starting, or held up); )"
            R"(nothing changed, ask again"})");
  EXPECT_TRUE(server.inbox().take().empty());
}

// A run that ends with a request taken but not decided answers it as over, not never.
TEST(ControlServer, ARunThatEndsAnswersWhatItTook) {
  ControlServer server(any_port(), kToken, std::chrono::hours(1));
  std::thread run([&server] {
    while (server.inbox().take().empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    server.refuse_steering("the run is over: stopped");
  });
  httplib::Client client("127.0.0.1", server.port());
  const auto r = client.Post(std::string("/api/save?token=") + kToken);
  run.join();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 409);
  EXPECT_EQ(r->body, R"({"error":"the run is over: stopped"})");
  EXPECT_EQ(client.Post(std::string("/api/save?token=") + kToken)->status, 409);
}

// Bound beyond this machine, the run's state is read with the token only.
TEST(ControlServer, BeyondLoopbackReadingNeedsTheTokenToo) {
  ControlServer server(any_port("0.0.0.0"), kToken);
  server.publish(RunState{});
  httplib::Client client("127.0.0.1", server.port());
  EXPECT_EQ(client.Get("/api/state")->status, 403);
  EXPECT_EQ(client.Get("/api/display/0.png")->status, 403);
  EXPECT_EQ(client.Get(std::string("/api/state?token=") + kToken)->status, 200);
  EXPECT_EQ(client.Get("/")->status, 200);  // the page itself holds nothing of the run
}

TEST(ControlServer, ATakenPortIsOneLine) {
  ControlServer first(any_port(), kToken);
  HttpAddress same = any_port();
  same.port = first.port();
  try {
    ControlServer second(same, kToken);
    FAIL() << "a second server listened on the same port";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "--http 127.0.0.1:" + std::to_string(first.port()) +
                  ": cannot listen (the port is taken, or the address is not this machine's)");
  }
}

TEST(ControlServer, AHostilePeerGetsRefusalsNotACrash) {
  ControlServer server(any_port(), kToken);
  httplib::Client client("127.0.0.1", server.port());
  const std::string big(1 << 20, 'x');
  const auto huge = client.Post(std::string("/api/stop?token=") + kToken, big, "text/plain");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->status, 413);
  EXPECT_TRUE(server.inbox().take().empty());
  EXPECT_EQ(client.Get("/api/display/99999.png")->status, 404);
  EXPECT_EQ(client.Get("/api/picture/..%2F..%2Fetc%2Fpasswd")->status, 404);
  EXPECT_EQ(client.Get("/api/state")->status, 200);  // still serving
}

TEST(TokenAndPictures, TokensAreRandomAndComparedWhole) {
  const std::string a = make_access_token(), b = make_access_token();
  EXPECT_EQ(a.size(), 32u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
  EXPECT_TRUE(token_matches(a, a));
  EXPECT_FALSE(token_matches(a.substr(0, 31), a));
  EXPECT_FALSE(token_matches("", ""));  // no token never matches
}

TEST(TokenAndPictures, EveryNthPixel) {
  const RgbImage p = gradient(10, 7);
  const RgbImage s = every_nth_pixel(p, 3);
  ASSERT_EQ(s.width(), 4);
  ASSERT_EQ(s.height(), 3);
  EXPECT_EQ(s.at(3, 2), p.at(9, 6));
  EXPECT_EQ(every_nth_pixel(p, 1).bytes().size(), p.bytes().size());
}

}  // namespace
}  // namespace l2
