// The control page in a real browser (Debian's Chromium, driven by tests/browser/control_page.mjs
// with playwright-core, which downloads no browser): it shows the wall's displays, the picture
// it shows of a display is that display's pixels, Pause stops the frame number, Save and Stop
// work from the page; a session's windows are dragged, resized (wheel, pinch) and raised there.
#include <nlohmann/json.hpp>

#include "browser_script.hpp"

namespace l2::testing_support {
namespace {

TEST(ControlPageBrowser, ShowsTheDisplaysAndSteersTheRun) {
  if (const std::string why = browser_missing(); !why.empty()) GTEST_SKIP() << why;
  PageRun run("browser", {"--frames", "100000", "--keep", "none"});
  const fs::path dir = run.out().parent_path();
  const std::string command =
      fmt::format("exec node '{}' '{}' '{}' > '{}' 2> '{}'",
                  (fs::path(L2_SOURCE_DIR) / "tests/browser/control_page.mjs").string(), run.url(),
                  dir.string(), (dir / "browser.json").string(), (dir / "browser.log").string());
  ChildProcess browser({"/bin/sh", "-c", command});
  const auto ended = browser.wait_for(120s);
  ASSERT_TRUE(ended) << "the browser script did not end";
  ASSERT_EQ(ended->code, 0) << slurp(dir / "browser.log") << run.output();
  const auto seen = nlohmann::json::parse(slurp(dir / "browser.json"));

  EXPECT_EQ(seen["displays"], 4);  // the default wall: 2x2
  EXPECT_EQ(seen["title"], "l2wall: 2x2 k-d wall");
  EXPECT_EQ(seen["frame_paused"], seen["frame_later"]) << "frames went on while paused";
  EXPECT_TRUE(seen["end"].get<std::string>() == "ended" ||
              seen["end"].get<std::string>() == "not reachable (run ended?)")
      << seen.dump();
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();

  // The picture the page showed of display 0 is every Nth pixel of what the run saved of it.
  const int frame = seen["frame_paused"];
  const int scale = seen["scale"];
  const RgbImage saved = read_png(run.out() / fmt::format("frame-{}", frame) / "display-0.png");
  const RgbImage shown = read_png(dir / "page-display-0.png");
  ASSERT_EQ(shown.width(), (saved.width() + scale - 1) / scale);
  ASSERT_EQ(shown.height(), (saved.height() + scale - 1) / scale);
  int differ = 0;
  for (int y = 0; y < shown.height(); ++y)
    for (int x = 0; x < shown.width(); ++x)
      differ += shown.at(x, y) != saved.at(x * scale, y * scale);
  EXPECT_EQ(differ, 0) << "of " << shown.width() * shown.height() << " pixels";
  EXPECT_NE(slurp(run.out() / "summary.txt").find("control page: 1 pause, 1 save, stopped"),
            std::string::npos);
  expect_clean(run);
}

// A session's windows dragged and raised on the page: the run moves and raises the window the
// page showed, keeping its size, and the page then shows it where the displays do.
TEST(ControlPageBrowser, MovesAndRaisesASessionsWindow) {
  if (const std::string why = browser_missing(); !why.empty()) GTEST_SKIP() << why;
  const std::string session = (fs::path(L2_SOURCE_DIR) / "examples/sessions/windows.toml").string();
  PageRun run("browser-windows",
              {"--scene", "session", "--session", session, "--frames", "100000", "--keep", "none"});
  const auto seen = session_script(run, "drag_window");
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();

  EXPECT_EQ(seen["windows"], 4) << seen.dump();
  EXPECT_EQ(seen["labels"][0], "0: mesh") << seen.dump();
  // examples/sessions/windows.toml's first window, dragged right and down, its size kept.
  EXPECT_EQ(seen["before"]["x"], 40);
  EXPECT_EQ(seen["before"]["y"], 30);
  const int x = seen["after"]["x"], y = seen["after"]["y"];
  EXPECT_GT(x, 40);
  EXPECT_GT(y, 30);
  EXPECT_EQ(seen["after"]["width"], 760);
  EXPECT_EQ(seen["after"]["height"], 560);
  EXPECT_EQ(seen["front"], 0);
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_NE(summary.find(fmt::format("windows: move 0 {} {} 760 560 from frame ", x, y)),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("windows: raise 0 from frame "), std::string::npos) << summary;
  expect_clean(run);
}

// Where the canvas point `at` lies across a window, as a fraction of its width and height: a
// resize about that point keeps it.
std::pair<double, double> across(const nlohmann::json& w, const nlohmann::json& at) {
  return {(at["x"].get<double>() - w["x"].get<double>()) / w["width"].get<double>(),
          (at["y"].get<double>() - w["y"].get<double>()) / w["height"].get<double>()};
}

// A session's windows resized with the wheel and a two-finger pinch and raised by a tap on the
// page: the run resizes each about the point the gesture was about, its shape kept, and raises
// the window tapped.
TEST(ControlPageBrowser, ResizesWithWheelAndPinchAndRaisesWithATap) {
  if (const std::string why = browser_missing(); !why.empty()) GTEST_SKIP() << why;
  const std::string session = (fs::path(L2_SOURCE_DIR) / "examples/sessions/windows.toml").string();
  PageRun run("browser-resize",
              {"--scene", "session", "--session", session, "--frames", "100000", "--keep", "none"});
  const auto seen = session_script(run, "resize_window");
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();
  ASSERT_TRUE(seen.contains("front")) << seen.dump();

  // examples/sessions/windows.toml's first window, 760x560 at (40, 30), grown by the wheel.
  const auto& wheeled = seen["wheel_after"];
  EXPECT_EQ(seen["wheel_before"]["width"], 760);
  const int w0 = wheeled["width"], h0 = wheeled["height"];
  EXPECT_GT(w0, 760) << seen.dump();
  EXPECT_NEAR(w0 * 560.0 / 760.0, h0, 1.0) << "its shape kept";
  const auto [u0, v0] = across(seen["wheel_before"], seen["wheel_at"]);
  const auto [u1, v1] = across(wheeled, seen["wheel_at"]);
  EXPECT_NEAR(u0, u1, 2.0 / w0) << "the point under the wheel stays under it";
  EXPECT_NEAR(v0, v1, 2.0 / h0);

  // The second, 560x520 at (720, 420), pinched from 80 to 160 pixels apart: twice as large,
  // about the fingers' centre.
  const auto& pinched = seen["pinch_after"];
  EXPECT_EQ(seen["pinch_before"]["width"], 560);
  EXPECT_EQ(pinched["width"], 1120) << seen.dump();
  EXPECT_EQ(pinched["height"], 1040);
  const auto [p0, q0] = across(seen["pinch_before"], seen["pinch_at"]);
  const auto [p1, q1] = across(pinched, seen["pinch_at"]);
  EXPECT_NEAR(p0, p1, 2.0 / 1120) << "the fingers' centre stays between them";
  EXPECT_NEAR(q0, q1, 2.0 / 1040);

  EXPECT_EQ(seen["front"], 0) << "the tapped window raised";
  const std::string summary = slurp(run.out() / "summary.txt");
  for (const auto* w : {&wheeled, &pinched}) {
    const auto& r = *w;
    EXPECT_NE(summary.find(fmt::format("windows: move {} {} {} {} {} from frame ",
                                       r["id"].get<int>(), r["x"].get<int>(), r["y"].get<int>(),
                                       r["width"].get<int>(), r["height"].get<int>())),
              std::string::npos)
        << summary;
  }
  EXPECT_NE(summary.find("windows: raise 0 from frame "), std::string::npos) << summary;
  // One command per gesture, not one per wheel notch or finger step.
  for (const std::string moved : {"windows: move 0 ", "windows: move 1 "}) {
    std::size_t count = 0;
    for (auto at = summary.find(moved); at != std::string::npos; at = summary.find(moved, at + 1))
      ++count;
    EXPECT_EQ(count, 1U) << summary;
  }
  expect_clean(run);
}

}  // namespace
}  // namespace l2::testing_support
