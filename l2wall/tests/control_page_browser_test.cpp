// The control page in a real browser (Debian's Chromium, driven by tests/browser/control_page.mjs
// with playwright-core, which downloads no browser): it shows the wall's displays, the picture
// it shows of a display is that display's pixels, Pause stops the frame number, Save and Stop
// work from the page; a session's windows are dragged and raised there.
#include <nlohmann/json.hpp>

#include "control_page_run.hpp"

namespace l2::testing_support {
namespace {

// Why the browser test cannot run here, or empty.
std::string browser_missing() {
  const fs::path browser = fs::path(L2_SOURCE_DIR) / "tests/browser";
  if (!fs::exists("/usr/bin/chromium")) return "no /usr/bin/chromium (scripts/install-deps.sh)";
  if (std::system("command -v node >/dev/null 2>&1") != 0) return "no node";
  if (!fs::exists(browser / "node_modules/playwright-core"))
    return "no tests/browser/node_modules (scripts/install-deps.sh runs npm ci there)";
  return {};
}

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
  const fs::path dir = run.out().parent_path();
  const std::string command =
      fmt::format("exec node '{}' '{}' > '{}' 2> '{}'",
                  (fs::path(L2_SOURCE_DIR) / "tests/browser/drag_window.mjs").string(), run.url(),
                  (dir / "windows.json").string(), (dir / "windows.log").string());
  ChildProcess browser({"/bin/sh", "-c", command});
  const auto ended = browser.wait_for(120s);
  ASSERT_TRUE(ended) << "the browser script did not end";
  ASSERT_EQ(ended->code, 0) << slurp(dir / "windows.log") << run.output();
  const auto seen = nlohmann::json::parse(slurp(dir / "windows.json"));
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

}  // namespace
}  // namespace l2::testing_support
