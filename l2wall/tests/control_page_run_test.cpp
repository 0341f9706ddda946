// `l2wall run --http`: a live run steered over HTTP as a script (or the page) does: the state
// follows the run, a pause holds the frame, a save writes exactly what the page shows, a request
// without the token changes nothing, and stop ends the run as q does. The page itself in a real
// browser: control_page_browser_test.cpp.
#include <httplib.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "control_page_run.hpp"

namespace l2::testing_support {
namespace {

TEST(ControlPageRun, SteeredOverHttp) {
  PageRun run("steer", {"--frames", "100000", "--keep", "none"});
  httplib::Client& http = run.client();

  run.wait_for_frame(3);
  const auto refused = http.Post("/api/pause", "", "text/plain");  // no token
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 403);
  EXPECT_EQ(refused->body, R"({"error":"this needs the run's token"})");
  const int before = run.state()["frame"];
  run.wait_for_frame(before + 3);  // still running: the refusal changed nothing
  EXPECT_FALSE(run.state()["paused"].get<bool>());

  // The answer is the run's decision, taken at its next frame boundary.
  EXPECT_EQ(run.post("pause"),
            nlohmann::json({{"done", "paused: READY held back, the pipeservers wait"}}));
  const nlohmann::json paused = run.wait_for([](const nlohmann::json& s) { return s["paused"]; });
  const int held = paused["frame"];
  std::this_thread::sleep_for(500ms);
  EXPECT_EQ(run.state()["frame"], held) << "frames went on while paused";

  // What the page shows of display 1 is what the run saves of it: byte for byte.
  const RgbImage shown = run.display(1);
  // A paused run still takes requests and answers them.
  const fs::path saved = run.out() / fmt::format("frame-{}", held) / "display-1.png";
  EXPECT_EQ(run.post("save"),
            nlohmann::json({{"done", "saved the displays to " + saved.parent_path().string()}}));
  ASSERT_TRUE(fs::exists(saved));
  EXPECT_TRUE(read_png(saved) == shown);
  const RgbImage small = run.display(1, 8);
  EXPECT_EQ(small.width(), (shown.width() + 7) / 8);
  EXPECT_EQ(small.at(5, 3), shown.at(40, 24));

  // What the run cannot do is refused in the answer, with the reason its events list too.
  const std::string no_balance =
      "balance not switched: this run does not balance (start it with --balance or [balance])";
  EXPECT_EQ(run.post("balance?mode=kd", 409), nlohmann::json({{"error", no_balance}}));
  const std::string no_session =
      "window not changed: this run shows no session (start it with --scene session)";
  EXPECT_EQ(run.post("window?action=raise&id=1", 409), nlohmann::json({{"error", no_session}}));
  run.wait_for([&](const nlohmann::json& s) {
    const std::string events = s["events"].dump();
    return events.find(no_balance) != std::string::npos &&
           events.find(no_session) != std::string::npos;
  });

  EXPECT_EQ(run.post("resume"), nlohmann::json({{"done", "resumed"}}));
  run.wait_for_frame(held + 3);
  EXPECT_EQ(run.post("stop"), nlohmann::json({{"done", "stopped from the control page"}}));
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_TRUE(std::regex_search(
      summary, std::regex("control page: 1 pause, 1 save, stopped from the page at frame \\d+")))
      << summary;
  expect_clean(run);
}

// A balanced run: the page switches its mode, the summary says from which frame.
TEST(ControlPageRun, SwitchesTheBalanceMode) {
  PageRun run("balance", {"--frames", "100000", "--keep", "none", "--balance", "strips"});
  run.wait_for_frame(3);
  EXPECT_EQ(run.state()["balance"]["mode"], "strips");
  EXPECT_EQ(run.post("balance?mode=kd"),
            nlohmann::json({{"done", "balance mode: kd from the next layout"}}));
  run.wait_for([](const nlohmann::json& s) { return s["balance"]["mode"] == "kd"; });
  EXPECT_EQ(
      run.post("balance?mode=sideways", 400),
      nlohmann::json(
          {{"error",
            "balance not switched: balance mode 'sideways': expected static, strips or kd"}}));
  run.post("stop");
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_TRUE(std::regex_search(summary, std::regex("balance: switched to kd at frame \\d+")))
      << summary;
}

// A port already taken is one line before any pipeserver starts.
TEST(ControlPageRun, ATakenPortIsRefusedAtStart) {
  HeldPort held;
  WallRun run("taken", {"--frames", "3", "--http", fmt::format("127.0.0.1:{}", held.port)});
  EXPECT_EQ(run.wait(60s).code, 1);
  EXPECT_EQ(run.output(), fmt::format("l2wall: --http 127.0.0.1:{}: cannot listen (the port is "
                                      "taken, or the address is not this machine's)\n",
                                      held.port));
  EXPECT_FALSE(fs::exists(run.out() / "pipeserver-0.log"));
}

TEST(ControlPageRun, ABadAddressIsAUsageError) {
  WallRun run("bad", {"--frames", "3", "--http", "80800"});
  EXPECT_EQ(run.wait(60s).code, 2);
  EXPECT_NE(run.output().find("--http: '80800' is not a port 0..65535"), std::string::npos)
      << run.output();
}

// `l2wall view OUT [args]` on a finished run's folder, its stderr to `log`.
ChildProcess start_view(const WallRun& run, const std::string& args, const fs::path& log) {
  return ChildProcess({"/bin/sh", "-c",
                       fmt::format("exec '{}' view '{}' {} 2> '{}'", L2WALL_PATH,
                                   run.out().string(), args, log.string())});
}

// The port and token `l2wall view` prints to `log` once it serves (waited for up to a minute);
// empty when it printed none.
struct ViewAddress {
  int port = 0;
  std::string token, said;
};
ViewAddress view_address(const fs::path& log) {
  const std::regex printed("l2wall view: http://127\\.0\\.0\\.1:(\\d+)/\\?token=([0-9a-f]+)");
  std::smatch m;
  ViewAddress a;
  for (int i = 0; i < 3000 && !std::regex_search(a.said = slurp(log), m, printed); ++i)
    std::this_thread::sleep_for(20ms);
  if (m.empty()) return a;
  a.port = std::stoi(m[1]);
  a.token = m[2];
  return a;
}

// `l2wall view OUT`: a finished run's folder served as the page serves a live one, nothing to
// steer.
TEST(ControlPageView, ServesAFinishedRun) {
  WallRun run("view", {"--frames", "6", "--keep", "every"});
  ASSERT_EQ(run.wait(60s).code, 0) << run.output();
  const fs::path log = run.out().parent_path() / "view.txt";
  ChildProcess view = start_view(run, "--http 127.0.0.1:0", log);
  const ViewAddress at = view_address(log);
  ASSERT_GT(at.port, 0) << at.said;
  httplib::Client http("127.0.0.1", at.port);
  const auto state = http.Get("/api/state");
  ASSERT_TRUE(state);
  const auto s = nlohmann::json::parse(state->body);
  EXPECT_EQ(s["live"], false);
  EXPECT_EQ(s["frame"], 5);           // the last kept
  EXPECT_EQ(s["latency_frames"], 1);  // frame 5's, from report.csv, as the live page said
  EXPECT_EQ(s["displays"].size(), 4u);
  EXPECT_EQ(s["pipeservers"].size(), 4u);
  EXPECT_EQ(s["pipeservers"][0]["recent"].size(), 6u);
  EXPECT_EQ(s["ended"].get<std::string>().rfind("l2wall run: 6 frames on 4 displays", 0), 0u);
  EXPECT_NE(s["pictures"].dump().find("frame-2~display-1.png"), std::string::npos);

  const auto display = http.Get("/api/display/0.png");
  ASSERT_TRUE(display);
  const fs::path got = run.out().parent_path() / "view-display-0.png";
  std::ofstream(got, std::ios::binary) << display->body;
  EXPECT_TRUE(read_png(got) == read_png(run.out() / "frame-5/display-0.png"));
  const auto picture = http.Get("/api/picture/frame-2~display-1.png");
  ASSERT_TRUE(picture);
  EXPECT_EQ(picture->body, slurp(run.out() / "frame-2/display-1.png"));
  EXPECT_EQ(http.Get("/api/picture/..~summary.txt")->status, 404);

  const auto steer = http.Post(fmt::format("/api/pause?token={}", at.token), "", "text/plain");
  ASSERT_TRUE(steer);
  EXPECT_EQ(steer->status, 409);
  EXPECT_EQ(steer->body, R"({"error":"the run is over: nothing to steer"})");

  kill(view.pid(), SIGINT);
  const auto ended = view.wait_for(60s);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->code, 0);
}

// The page draws each panel as it hangs: on walls/mixed-hang.toml display 1 hangs at 270, so its
// state is its canvas rectangle (720x1280) and its picture is its frame turned upright: canvas
// offset (u, v) shows panel pixel (1279 - v, u) (docs/wall-file.md: (x, y) shows (y, ch - 1 - x)).
TEST(ControlPageView, ShowsATurnedPanelAsItHangs) {
  const std::string wall = std::string(L2_SOURCE_DIR) + "/walls/mixed-hang.toml";
  WallRun run("view-turned", {"--wall", wall, "--frames", "2", "--keep", "1"});
  ASSERT_EQ(run.wait(60s).code, 0) << run.output();
  const fs::path log = run.out().parent_path() / "view-turned.txt";
  ChildProcess view = start_view(run, fmt::format("--wall '{}' --http 127.0.0.1:0", wall), log);
  const ViewAddress at = view_address(log);
  ASSERT_GT(at.port, 0) << at.said;
  httplib::Client http("127.0.0.1", at.port);
  const auto state = http.Get("/api/state");
  ASSERT_TRUE(state);
  const auto s = nlohmann::json::parse(state->body);
  EXPECT_EQ(s["displays"][1]["x"], 1320);
  EXPECT_EQ(s["displays"][1]["width"], 720);
  EXPECT_EQ(s["displays"][1]["height"], 1280);
  EXPECT_EQ(s["displays"][1]["rotation"], 270);
  EXPECT_EQ(s["displays"][2]["flip"], "horizontal");
  const auto display = http.Get("/api/display/1.png");
  ASSERT_TRUE(display);
  const fs::path got = run.out().parent_path() / "view-turned-display-1.png";
  std::ofstream(got, std::ios::binary) << display->body;
  const RgbImage page = read_png(got);
  const RgbImage frame = read_png(run.out() / "frame-1/display-1.png");
  ASSERT_EQ(page.width(), 720);
  ASSERT_EQ(page.height(), 1280);
  for (const auto& [u, v] :
       {std::pair{0, 0}, std::pair{719, 0}, std::pair{300, 700}, std::pair{719, 1279}})
    EXPECT_EQ(page.at(u, v), frame.at(1279 - v, u)) << u << "," << v;
  kill(view.pid(), SIGINT);
  const auto ended = view.wait_for(60s);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->code, 0);
}

TEST(ControlPageView, AFrameNotKeptIsNamed) {
  WallRun run("view-frame", {"--frames", "3", "--keep", "0,2"});
  ASSERT_EQ(run.wait(60s).code, 0) << run.output();
  const fs::path log = run.out().parent_path() / "view.txt";
  ChildProcess view = start_view(run, "--frame 1", log);
  const auto ended = view.wait_for(60s);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->code, 1);
  EXPECT_EQ(slurp(log), fmt::format("l2wall view: --frame 1: {} holds no frame-1/ (kept: 0, 2)\n",
                                    run.out().string()));
}

}  // namespace
}  // namespace l2::testing_support
