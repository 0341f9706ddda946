// `l2wall run --balance strips`: the hosts re-tile live, every host switching to frame k+1's
// layout together, and since sort-first rendering is exact per pixel whatever the tiling, the
// displays of every frame equal those of a static run byte for byte, each host's frame stamp
// aside (it sits in its first tile, which the layout moves). Real processes, links and sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "balance/control_messages.hpp"
#include "frame_stamp.hpp"
#include "image/png_io.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kFrames = 10;
// Frames compared: the first switch from the wall's tiling to the strips, two moving toward the
// load, and the last (writing every frame's pictures would take most of the test's time).
const std::vector<int> kCompared{1, 2, 3, 9};

using Spot = std::pair<int, int>;

// Where each pipeserver's stamp lands on display `d` in `layout`.
std::vector<Spot> stamps_on(const TileLayout& layout, int d) {
  std::vector<Spot> spots;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    const DisplayTile& t = plan.tiles.front().tile;
    if (t.display == d) spots.emplace_back(t.on_display.x, t.on_display.y);
  }
  return spots;
}

int stamp_at(const RgbImage& image, const Spot& s) {
  const Rgb px = image.at(s.first, s.second);
  const std::uint8_t bytes[3] = {px.r, px.g, px.b};
  return decode_stamp(bytes);
}

// The layouts the balanced run's hosts rendered each frame in, as it wrote them.
std::vector<TileLayout> layouts_of(const WallRun& run, const Wall& wall) {
  std::vector<TileLayout> layouts;
  std::istringstream in(slurp(run.out() / "layouts.txt"));
  for (std::string line; std::getline(in, line);) {
    const LayoutMessage m = decode_layout(line);
    EXPECT_EQ(m.frame, static_cast<int>(layouts.size()));
    layouts.push_back(plan_from_message(wall, m));
  }
  return layouts;
}

TEST(LiveRunBalance, StripsRetileLiveWithTheDisplaysOfAStaticRun) {
  const std::vector<std::string> common{"--scene",   "strips", "--frames", std::to_string(kFrames),
                                        "--refresh", "0",      "--keep",   "1,2,3,9"};
  std::vector<std::string> balanced_args = common;
  balanced_args.insert(balanced_args.end(), {"--balance", "strips"});
  // Side by side: each run waits for its own pipeservers much of the time.
  WallRun fixed("balance-static", common);
  WallRun balanced("balance-strips", balanced_args);
  ASSERT_TRUE(fixed.wait(30s).ok()) << fixed.output();
  ASSERT_TRUE(balanced.wait(30s).ok()) << balanced.output();
  const std::string output = balanced.output();

  // No swap showed frames of two layouts, and there were swaps to check.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m,
                                std::regex("balance: (\\d+) of (\\d+) group swaps showed frames of "
                                           "two layouts")))
      << output;
  EXPECT_EQ(m[1].str(), "0");
  EXPECT_GE(std::stoi(m[2].str()), kFrames);  // every frame swapped in
  ASSERT_TRUE(std::regex_search(output, m, std::regex("balance strips: (\\d+) layouts, strips")))
      << output;
  const int layouts_counted = std::stoi(m[1].str());

  const Wall wall = default_wall();
  const TileLayout start = plan_layout(wall);
  const std::vector<TileLayout> layouts = layouts_of(balanced, wall);
  ASSERT_EQ(layouts.size(), static_cast<std::size_t>(kFrames));
  // The run did re-tile: the strips' first layout and later ones moved by the load.
  std::set<std::vector<Spot>> distinct;
  for (const TileLayout& l : layouts) distinct.insert(stamps_on(l, 0));
  EXPECT_GE(distinct.size(), 3u);
  EXPECT_GE(layouts_counted, static_cast<int>(distinct.size()));

  for (int k : kCompared) {
    const TileLayout& now = layouts[static_cast<std::size_t>(k)];
    for (int d = 0; d < static_cast<int>(wall.displays.size()); ++d) {
      const auto file = fs::path(fmt::format("frame-{}", k)) / fmt::format("display-{}.png", d);
      const RgbImage a = read_png(fixed.out() / file);
      const RgbImage b = read_png(balanced.out() / file);
      ASSERT_EQ(a.width(), b.width());
      ASSERT_EQ(a.height(), b.height());
      std::vector<Spot> skip = stamps_on(start, d);
      for (const Spot& s : skip) EXPECT_EQ(stamp_at(a, s), k) << file;
      for (const Spot& s : stamps_on(now, d)) {
        EXPECT_EQ(stamp_at(b, s), k) << file;
        skip.push_back(s);
      }
      long differ = 0;
      for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
          if (std::find(skip.begin(), skip.end(), Spot{x, y}) != skip.end()) continue;
          differ += !(a.at(x, y) == b.at(x, y));
        }
      }
      EXPECT_EQ(differ, 0) << file;
    }
  }
  expect_clean(fixed);
  expect_clean(balanced);
}

}  // namespace
}  // namespace l2
