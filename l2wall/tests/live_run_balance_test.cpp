// `l2wall run --balance strips`: the hosts re-tile live, every host switching to frame k+1's
// layout together, and since sort-first rendering is exact per pixel whatever the tiling, the
// displays of every frame equal those of a static run byte for byte, each host's frame stamp
// aside (it sits in its first tile, which the layout moves). Real processes, links and sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
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

// Every display of the kept frames `frames` equals the static run's (on the default wall) byte
// for byte, the stamps aside, each saying the frame: in the static run where the default
// wall's plan puts them, in the balanced one (on `wall`) where that frame's layout does.
void expect_displays_of_the_static_run(const WallRun& fixed, const WallRun& balanced,
                                       const Wall& wall, const std::vector<TileLayout>& layouts,
                                       const std::vector<int>& frames) {
  const TileLayout start = plan_layout(default_wall());  // the static run's
  for (int k : frames) {
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
}

// No swap showed frames of two layouts, and there were swaps to check.
void expect_no_mixed_swaps(const std::string& output) {
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m,
                                std::regex("balance: (\\d+) of (\\d+) group swaps showed frames of "
                                           "two layouts")))
      << output;
  EXPECT_EQ(m[1].str(), "0");
  EXPECT_GE(std::stoi(m[2].str()), kFrames);  // every frame swapped in
}

// Patience for a loaded machine: writing the kept pictures holds the READYs of the next frame.
const std::vector<std::string> kCommon{
    "--scene", "strips",          "--frames", std::to_string(kFrames), "--refresh", "0", "--keep",
    "1,2,3,9", "--ready-timeout", "5000",     "--stall-timeout",       "60000"};

TEST(LiveRunBalance, StripsRetileLiveWithTheDisplaysOfAStaticRun) {
  std::vector<std::string> balanced_args = kCommon;
  balanced_args.insert(balanced_args.end(), {"--balance", "strips"});
  // Side by side: each run waits for its own pipeservers much of the time.
  WallRun fixed("balance-static", kCommon);
  WallRun balanced("balance-strips", balanced_args);
  ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
  ASSERT_TRUE(balanced.wait(120s).ok()) << balanced.output();
  const std::string output = balanced.output();

  expect_no_mixed_swaps(output);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m, std::regex("balance strips: (\\d+) layouts, strips")))
      << output;
  const int layouts_counted = std::stoi(m[1].str());

  const Wall wall = default_wall();
  const std::vector<TileLayout> layouts = layouts_of(balanced, wall);
  ASSERT_EQ(layouts.size(), static_cast<std::size_t>(kFrames));
  // The run did re-tile: the strips' first layout and later ones moved by the load.
  std::set<std::vector<Spot>> distinct;
  for (const TileLayout& l : layouts) distinct.insert(stamps_on(l, 0));
  EXPECT_GE(distinct.size(), 3u);
  EXPECT_GE(layouts_counted, static_cast<int>(distinct.size()));

  expect_displays_of_the_static_run(fixed, balanced, wall, layouts, kCompared);
  expect_clean(fixed);
  expect_clean(balanced);
}

// The paper's assignment on top of the strips ([balance] assignment = "heaviest-first", which
// only the wall file sets): the heaviest tile to the pipeserver that finishes first. Tiles
// change hosts, every host switching together, and the displays are still the static run's.
TEST(LiveRunBalance, HeaviestFirstMovesTilesBetweenHostsWithTheDisplaysOfAStaticRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-heaviest-{}", getpid());
  fs::create_directories(dir);
  // Roomier framebuffers than the default wall's: more of the layouts heaviest first plans fit.
  const fs::path wall_file = write_roomy_default_wall(
      dir, "\n[balance]\nmode = \"strips\"\nassignment = \"heaviest-first\"\n");
  std::vector<std::string> balanced_args = kCommon;
  balanced_args.insert(balanced_args.end(), {"--wall", wall_file.string()});
  WallRun fixed("heaviest-static", kCommon);
  WallRun balanced("heaviest-strips", balanced_args);
  ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
  ASSERT_TRUE(balanced.wait(120s).ok()) << balanced.output();
  expect_no_mixed_swaps(balanced.output());

  const Wall wall = load_wall(wall_file);
  std::vector<LayoutMessage> lines;
  std::istringstream in(slurp(balanced.out() / "layouts.txt"));
  for (std::string line; std::getline(in, line);) lines.push_back(decode_layout(line));
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kFrames));
  // Moved: from frame 2 on (frame 1 is the even strips, dealt by the policy) some frame gives
  // its tiles other hosts than the last frame did, and other hosts than the wall's policy
  // ([pipeservers] assignment) would give those very tiles.
  int changed = 0, off_policy = 0;
  for (std::size_t k = 2; k < lines.size(); ++k) {
    changed += lines[k].pipeservers != lines[k - 1].pipeservers;
    Wall by_policy = wall;
    by_policy.tiling = {};
    by_policy.tiling.kind = TilingKind::List;
    by_policy.tiling.rects = lines[k].tiles;
    off_policy += layout_message(0, plan_layout(by_policy)).pipeservers != lines[k].pipeservers;
  }
  std::printf("heaviest first: %d of %d frames from frame 2 on changed hosts, %d off the policy\n",
              changed, kFrames - 2, off_policy);
  EXPECT_GE(changed, 1);
  EXPECT_GE(off_policy, 1);

  std::vector<TileLayout> layouts;
  for (const LayoutMessage& line : lines) layouts.push_back(plan_from_message(wall, line));
  expect_displays_of_the_static_run(fixed, balanced, wall, layouts, kCompared);
  expect_clean(fixed);
  expect_clean(balanced);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
