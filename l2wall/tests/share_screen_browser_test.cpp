// A screen shared from the control page in a real browser (Debian's Chromium, its fake screen,
// tests/browser/share_screen.mjs) into a session run: the displays saved while it is shared
// show the fake screen's dark green in the share's window, and nothing else changed; once the
// browser stops sharing, the window is gone and the displays are as before it.
#include <nlohmann/json.hpp>

#include "browser_script.hpp"

namespace l2::testing_support {
namespace {

// Chromium's fake screen is dark green (0, 135, 0) but for a moving shape and its text; the
// JPEG and the wall's sampling keep it within this of that.
constexpr int kTolerance = 40;

bool fake_screen_green(const Rgb& c) {
  return c.r <= kTolerance && std::abs(c.g - 135) <= kTolerance && c.b <= kTolerance;
}

// The frame number of "saved the displays to OUT/frame-N".
int saved_frame(const nlohmann::json& done) {
  const std::string text = done.get<std::string>();
  return std::stoi(text.substr(text.rfind("frame-") + 6));
}

struct Compared {
  long inside = 0, green_inside = 0;  // pixels well inside the window, and of those green
  long outside_changed = 0;           // pixels off the window that differ from `before`
};

// The displays of frame `frame` against frame `before`, every pipeserver's frame stamp aside:
// what lies inside `window` (canvas; an empty one: none) and what changed outside it.
Compared compare(const WallRun& run, const Wall& wall, int before, int frame, const Rect& window) {
  const TileLayout layout = plan_layout(wall);
  const Rect inner{window.x + 3, window.y + 3, window.w - 6, window.h - 6};
  const Rect outer{window.x - 1, window.y - 1, window.w + 2, window.h + 2};
  Compared c;
  for (const Display& display : wall.displays) {
    const auto png = [&](int k) {
      return read_png(run.out() / fmt::format("frame-{}", k) /
                      fmt::format("display-{}.png", display.id));
    };
    const RgbImage was = png(before), shown = png(frame);
    std::vector<std::pair<int, int>> stamps;
    for (const PipeserverPlan& plan : layout.pipeservers) {
      const DisplayTile& t = plan.tiles.front().tile;
      if (t.display == display.id) stamps.emplace_back(t.on_display.x, t.on_display.y);
    }
    const Rect r = display.on_canvas();
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        if (std::find(stamps.begin(), stamps.end(), std::pair{x, y}) != stamps.end()) continue;
        const Rect at{r.x + x, r.y + y, 1, 1};
        if (!window.empty() && intersect(inner, at) == at) {
          ++c.inside;
          c.green_inside += fake_screen_green(shown.at(x, y));
        } else if (window.empty() || intersect(outer, at).empty()) {
          c.outside_changed += shown.at(x, y) != was.at(x, y);
        }
      }
    }
  }
  return c;
}

TEST(ControlPageBrowser, SharesAScreenIntoASessionAndClosesItWhenStopped) {
  if (const std::string why = browser_missing(); !why.empty()) GTEST_SKIP() << why;
  const std::string session = (fs::path(L2_SOURCE_DIR) / "examples/sessions/share.toml").string();
  PageRun run("browser-share",
              {"--scene", "session", "--session", session, "--frames", "100000", "--keep", "none"});
  const auto seen = session_script(run, "share_screen");
  EXPECT_EQ(run.wait(60s).code, 0) << run.output();
  ASSERT_TRUE(seen.contains("after")) << seen.dump();

  EXPECT_EQ(seen["slots"], 2);
  // examples/sessions/share.toml has window 0: the share is window 1, in front, named as the
  // page said, its frames the size of Chromium's fake screen (wider than tall, as the
  // browser's screen).
  EXPECT_EQ(seen["window"]["id"], 1) << seen.dump();
  EXPECT_EQ(seen["front"], 1);
  EXPECT_EQ(seen["share"]["name"], "tester");
  const int w = seen["share"]["width"], h = seen["share"]["height"];
  EXPECT_GT(w, h);
  EXPECT_EQ(seen["share"]["refused"], 0);
  const std::string size = fmt::format("{}x{}", w, h);
  EXPECT_NE(seen["page_says"].get<std::string>().find("window 1 (tester, " + size + "): "),
            std::string::npos)
      << seen.dump();
  // Centred on the default wall's 1300x980 canvas, half its width, the share's aspect kept.
  const Rect window{seen["window"]["x"], seen["window"]["y"], seen["window"]["width"],
                    seen["window"]["height"]};
  EXPECT_EQ(window.w, 650);
  EXPECT_NEAR(window.h, 650.0 * h / w, 1.0);
  EXPECT_NEAR(window.x + window.w / 2.0, 650, 1.0);
  EXPECT_NEAR(window.y + window.h / 2.0, 490, 1.0);

  const Wall wall = default_wall();
  const int before = saved_frame(seen["before"]), during = saved_frame(seen["during"]),
            after = saved_frame(seen["after"]);
  const Compared shared = compare(run, wall, before, during, window);
  ASSERT_GT(shared.inside, 0);
  EXPECT_GT(shared.green_inside, shared.inside * 8 / 10)
      << shared.green_inside << " of " << shared.inside << " pixels of the window green";
  EXPECT_EQ(shared.outside_changed, 0) << "pixels off the share's window changed";
  const Compared closed = compare(run, wall, before, after, Rect{});
  EXPECT_EQ(closed.outside_changed, 0) << "the displays once the share stopped";

  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_NE(summary.find("shares: window 1 shared by tester (" + size + ") from frame "),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("windows: close 1 from frame "), std::string::npos) << summary;
  expect_clean(run);
}

}  // namespace
}  // namespace l2::testing_support
