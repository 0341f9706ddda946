// Screens shared into a live session run over HTTP, as the page's script does but from here:
// the run opens a window per share up to the session's `shares`, refuses one more in one line,
// takes JPEG frames (made with libjpeg's encoder) and refuses hostile ones, and a share's
// window closed takes no more frames. The page itself in a real browser:
// share_screen_browser_test.cpp.
#include <httplib.h>

#include <nlohmann/json.hpp>

#include "control_page_run.hpp"
#include "test_jpeg.hpp"

namespace l2::testing_support {
namespace {

// POST /api/share/frame for `window`: the status and the answer's one line.
std::pair<int, std::string> send_frame(PageRun& run, int window, const std::string& body) {
  const auto r = run.client().Post(
      fmt::format("/api/share/frame?window={}&token={}", window, run.token()), body, "image/jpeg");
  if (!r) return {0, "no answer"};
  const auto j = nlohmann::json::parse(r->body);
  return {r->status,
          j.contains("done") ? j["done"].get<std::string>() : j["error"].get<std::string>()};
}

TEST(ShareRun, OpensWindowsUpToTheSharesAndTakesOnlyJpegFrames) {
  const std::string session = (fs::path(L2_SOURCE_DIR) / "examples/sessions/share.toml").string();
  PageRun run("share-run",
              {"--scene", "session", "--session", session, "--frames", "100000", "--keep", "none"});
  run.wait_for_frame(2);
  EXPECT_EQ(run.state()["shares"]["slots"], 2);
  // Centred on the 1300x980 canvas at its own size; the second where it was asked.
  EXPECT_EQ(run.post("share?width=640&height=360&name=alice"),
            nlohmann::json({{"done", "sharing alice as window 1 (640x360) at 330,310 640x360"}}));
  EXPECT_EQ(run.post("share?width=200&height=100&x=200&y=150"),
            nlohmann::json({{"done", "sharing browser as window 2 (200x100) at 100,100 200x100"}}));
  EXPECT_EQ(
      run.post("share?width=200&height=100", 409),
      nlohmann::json(
          {{"error", "not shared: all 2 share windows are in use (the session's shares = 2)"}}));

  EXPECT_EQ(send_frame(run, 1, test::two_halves(640, 360)),
            std::pair(200, std::string("frame 1 of window 1 taken")));
  EXPECT_EQ(send_frame(run, 1, "GIF89a\x01\x00\x01\x00"),
            std::pair(400, std::string("frame refused: not a JPEG (it starts 47 49 46 38)")));
  EXPECT_EQ(send_frame(run, 2, test::two_halves(640, 360)),
            std::pair(400, std::string("frame refused: declares 640x360 pixels, more than a "
                                       "shared frame may have (200x100)")));
  // The run takes the frame into the window's desktop at a frame boundary.
  const auto s = run.wait_for([](const nlohmann::json& j) {
    for (const auto& share : j["shares"]["shown"])
      if (share["window"] == 1 && share["shown"] == 1) return true;
    return false;
  });
  EXPECT_EQ(s["shares"]["shown"].size(), 2u) << s.dump();
  // No frame since: the share has stalled, and the displays keep its last frame, its left half
  // red and its right half blue across the canvas's two columns of displays.
  run.wait_for([](const nlohmann::json& j) {
    return j["shares"]["shown"][0]["seconds_since_frame"].get<double>() >= 1.0;
  });
  const nlohmann::json saved = run.post("save");
  const std::string folder = saved["done"].get<std::string>();
  const fs::path frame = folder.substr(folder.rfind(' ') + 1);
  for (const Display& d : default_wall().displays) {
    const Rect r = d.on_canvas();
    const Rgb want = r.x == 0 ? Rgb{255, 0, 0} : Rgb{0, 0, 255};
    const int x = r.x == 0 ? 400 : 900, y = r.y == 0 ? 350 : 600;  // inside the share's window
    const Rgb got = read_png(frame / fmt::format("display-{}.png", d.id)).at(x - r.x, y - r.y);
    EXPECT_LE(std::abs(got.r - want.r) + std::abs(got.g - want.g) + std::abs(got.b - want.b), 40)
        << "display " << d.id << " canvas " << x << "," << y;
  }

  EXPECT_EQ(run.post("window?action=close&id=1"),
            nlohmann::json({{"done", "window: close 1 from the next frame"}}));
  EXPECT_EQ(send_frame(run, 1, test::two_halves(640, 360)).first, 404);
  run.wait_for([](const nlohmann::json& j) {  // the frame it closes in on the displays
    for (const auto& w : j["windows"]["shown"])
      if (w["id"] == 1) return false;
    return true;
  });
  run.post("stop");
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_NE(summary.find("shares: window 1 shared by alice (640x360) from frame "),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("windows: close 1 from frame "), std::string::npos) << summary;
  expect_clean(run);
}

}  // namespace
}  // namespace l2::testing_support
