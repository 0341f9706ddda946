// Screens shared over HTTP (share_inbox.hpp): a real server on loopback, frames POSTed with
// cpp-httplib's client as the page's script does, made with libjpeg's encoder; hostile frames
// refused in one line, each share keeping its newest frame only.
#include <gtest/gtest.h>
#include <httplib.h>

#include <nlohmann/json.hpp>
#include <string>

#include "control_page/control_server.hpp"
#include "test_jpeg.hpp"

namespace l2 {
namespace {

constexpr const char* kShareToken = "0123456789abcdef0123456789abcdef";

struct SharedServer {
  SharedServer() : server(address(), kShareToken), client("127.0.0.1", server.port()) {
    server.shares()->open(12, "alice", 64, 32);
  }
  static HttpAddress address() {
    HttpAddress a;
    a.host = "127.0.0.1";
    return a;
  }
  // The answer's status and its one line ("done" or "error").
  std::pair<int, std::string> frame(const std::string& body, const std::string& query) {
    const auto res = client.Post("/api/share/frame?" + query, body, "image/jpeg");
    if (!res) return {0, "no answer"};
    const auto j = nlohmann::json::parse(res->body);
    return {res->status,
            j.contains("done") ? j["done"].get<std::string>() : j["error"].get<std::string>()};
  }
  std::pair<int, std::string> frame(const std::string& body) {
    return frame(body, std::string("window=12&token=") + kShareToken);
  }
  ControlServer server;
  httplib::Client client;
};

TEST(ShareServer, AFrameIsDecodedAndTheNewestKept) {
  SharedServer s;
  EXPECT_EQ(s.frame(test::two_halves(64, 32)),
            std::pair(200, std::string("frame 1 of window 12 taken")));
  EXPECT_EQ(s.frame(test::two_halves(64, 32)).first, 200);
  const std::optional<RgbImage> taken = s.server.shares()->take(12);
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->width(), 64);
  EXPECT_NEAR(taken->row(16)[8 * 3], 255, 12);       // red on the left
  EXPECT_NEAR(taken->row(16)[56 * 3 + 2], 255, 12);  // blue on the right
  EXPECT_FALSE(s.server.shares()->take(12));         // nothing newer
  const std::vector<PageShare> shares = s.server.shares()->shares(ShareInbox::Clock::now());
  ASSERT_EQ(shares.size(), 1u);
  EXPECT_EQ(shares[0].name, "alice");
  EXPECT_EQ(shares[0].received, 2);
  EXPECT_EQ(shares[0].shown, 1);
  EXPECT_EQ(shares[0].dropped, 1);  // the first, replaced before the run took it
  EXPECT_GE(shares[0].seconds_since_frame, 0.0);
}

TEST(ShareServer, HostileFramesAreRefusedInOneLine) {
  SharedServer s;
  const std::string good = test::two_halves(64, 32);
  EXPECT_EQ(s.frame("\x89PNG\r\n\x1a\n"),
            std::pair(400, std::string("frame refused: not a JPEG (it starts 89 50 4e 47)")));
  const auto cut = s.frame(good.substr(0, good.size() / 2));
  EXPECT_EQ(cut.first, 400);
  EXPECT_EQ(cut.second.rfind("frame refused: a damaged JPEG (", 0), 0u) << cut.second;
  EXPECT_EQ(s.frame(test::two_halves(128, 32)),
            std::pair(400, std::string("frame refused: declares 128x32 pixels, more than a shared "
                                       "frame may have (64x32)")));
  EXPECT_EQ(s.frame(test::two_halves(32, 32)),
            std::pair(400, std::string("frame refused: 32x32, but the share's frames are 64x32")));
  EXPECT_EQ(s.frame(good, "window=13&token=" + std::string(kShareToken)),
            std::pair(404, std::string("frame refused: window 13 shares no screen (stopped, or "
                                       "never started)")));
  EXPECT_EQ(s.frame(good, "window=12").first, 403);
  const auto huge = s.client.Post(std::string("/api/share/frame?window=12&token=") + kShareToken,
                                  std::string((16 << 20) + 1, 'x'), "image/jpeg");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->status, 413);
  EXPECT_EQ(s.server.shares()->shares(ShareInbox::Clock::now())[0].refused, 4);
  EXPECT_FALSE(s.server.shares()->take(12));  // nothing refused was kept
  EXPECT_EQ(s.frame(good).first, 200);        // and the share goes on
}

TEST(ShareServer, AClosedShareTakesNoFrames) {
  SharedServer s;
  s.server.shares()->close(12);
  EXPECT_EQ(s.frame(test::two_halves(64, 32)).first, 404);
  EXPECT_TRUE(s.server.shares()->shares(ShareInbox::Clock::now()).empty());
}

// A frame refused before its body is read (a share stopped while a frame was on its way, a
// missing token or window) leaves the connection ready for the client's next request: the
// body is read and dropped, not taken for that request, which a browser then saw answered 400
// with nothing (its next /api/state not JSON).
TEST(ShareServer, ARefusedFrameLeavesItsConnectionReadyForTheNextRequest) {
  SharedServer s;
  s.client.set_keep_alive(true);
  const std::string good = test::two_halves(64, 32);
  const std::string token = std::string("token=") + kShareToken;
  for (const auto& [query, status] : std::vector<std::pair<std::string, int>>{
           {"window=13&" + token, 404}, {"window=12", 403}, {token, 400}}) {
    const auto refused = s.client.Post("/api/share/frame?" + query, good, "image/jpeg");
    ASSERT_TRUE(refused) << query;
    EXPECT_EQ(refused->status, status) << query;
    const auto next = s.client.Get("/api/state");
    ASSERT_TRUE(next) << query;
    EXPECT_EQ(next->status, 200) << query << ": " << next->body;
    EXPECT_EQ(next->body, "{}") << query;
  }
  // Sent in chunks, without a length: refused (411), its chunks dropped.
  const auto chunked = s.client.Post(
      std::string("/api/share/frame?window=12&token=") + kShareToken,
      [&](std::size_t, httplib::DataSink& sink) {
        sink.write(good.data(), good.size());
        sink.done();
        return true;
      },
      "image/jpeg");
  ASSERT_TRUE(chunked);
  EXPECT_EQ(chunked->status, 411);
  const auto next = s.client.Get("/api/state");
  ASSERT_TRUE(next);
  EXPECT_EQ(next->status, 200) << next->body;
  EXPECT_EQ(s.frame(good).first, 200);
}

// A share request reaches the run as one line; a body on another route is refused unread.
TEST(ShareServer, AShareRequestIsALineForTheRun) {
  SharedServer s;
  std::string taken;
  std::thread run([&] {
    for (int i = 0; i < 500 && taken.empty(); ++i) {
      for (const ControlRequest& r : s.server.inbox().take()) {
        taken = r.argument;
        s.server.inbox().decide(r.ticket, {409, "not shared: all 1 share windows are in use"});
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
  const auto res = s.client.Post(
      std::string("/api/share?width=1280&height=720&x=100&name=bob%0Asmith&token=") + kShareToken);
  run.join();
  EXPECT_EQ(taken, "1280 720 100 -1 bobsmith");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 409);
  EXPECT_EQ(s.client.Post(std::string("/api/share?width=wide&token=") + kShareToken)->status, 400);
  const auto big = s.client.Post(std::string("/api/stop?token=") + kShareToken,
                                 std::string(8192, 'x'), "text/plain");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
}

}  // namespace
}  // namespace l2
