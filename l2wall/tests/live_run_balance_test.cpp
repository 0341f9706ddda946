// `l2wall run --balance strips`: the pipeservers re-tile live, every pipeserver switching to frame
// k+1's layout together, and since sort-first rendering is exact per pixel whatever the tiling, the
// displays of every frame equal those of a static run byte for byte, each pipeserver's frame stamp
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

#include "balanced_run.hpp"
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

// Every display of the kept frames `frames` equals the static run's (on the default wall) byte
// for byte, the stamps aside, each saying the frame.
void expect_displays_of_the_static_run(const WallRun& fixed, const WallRun& balanced,
                                       const std::vector<TileLayout>& layouts,
                                       const std::vector<int>& frames) {
  expect_displays_equal_stamps_aside(fixed, plan_layout(default_wall()), balanced, layouts, frames);
}

// How many frames "0-3, 7, 9-12" names.
int frames_in_ranges(const std::string& ranges) {
  int count = 0;
  std::istringstream in(ranges);
  for (std::string part; std::getline(in, part, ',');) {
    const std::size_t dash = part.find('-');
    count += dash == std::string::npos
                 ? 1
                 : std::stoi(part.substr(dash + 1)) - std::stoi(part.substr(0, dash)) + 1;
  }
  return count;
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
  ASSERT_TRUE(std::regex_search(
      output, m,
      std::regex("balance strips: (\\d+) layouts \\(from frames ([0-9, -]+)\\), strips routed "
                 "per layout: [0-9 to]+\n")))
      << output;
  const int layouts_counted = std::stoi(m[1].str());
  // The frames each layout started at, as ranges: as many frames as layouts, far fewer words.
  EXPECT_EQ(frames_in_ranges(m[2].str()), layouts_counted) << m[0];
  // Whether balancing paid, from frames 1 to 8 (measured on balanced layouts, planned from):
  // the figures and their ratio agree, and the verdict follows the ratio.
  ASSERT_TRUE(std::regex_search(
      output, m,
      std::regex("\nbalance: (paid|lost|no gain) in render time: the slowest pipeserver took "
                 "([0-9.]+) ms a frame \\(median\\); the wall's own layout, ([0-9.]+) ms at the "
                 "same costs \\(([0-9.]+)x\\)\n")))
      << output;
  const double gain = std::stod(m[4].str());
  EXPECT_NEAR(gain, std::stod(m[3].str()) / std::stod(m[2].str()),
              0.01 + 0.1 / std::stod(m[2].str()));
  // The verdict follows the ratio (printed rounded: away from the 5 % edges).
  if (gain > 1.06 || gain < 0.94 || (gain > 0.96 && gain < 1.04)) {
    EXPECT_EQ(m[1].str(), gain > 1.06 ? "paid" : gain < 0.94 ? "lost" : "no gain") << m[0];
  }
  EXPECT_NE(output.find("\nlimited by "), std::string::npos) << output;
  // The pipeservers' batch footprints reached the balancer: the strips scene's 100,000
  // triangles in strips of 16, 64 strips a batch, are 98 batches, all in view.
  EXPECT_NE(output.find("balance: tiles priced by their pixels and the batches they touch (98 "
                        "batches a frame at most)"),
            std::string::npos)
      << output;

  const Wall wall = default_wall();
  const std::vector<TileLayout> layouts = layouts_of(balanced, wall);
  ASSERT_EQ(layouts.size(), static_cast<std::size_t>(kFrames));
  // The run did re-tile: the strips' first layout and later ones moved by the load.
  std::set<std::vector<Spot>> distinct;
  for (const TileLayout& l : layouts) distinct.insert(first_tiles_on(l, 0));
  EXPECT_GE(distinct.size(), 3u);
  EXPECT_GE(layouts_counted, static_cast<int>(distinct.size()));

  expect_displays_of_the_static_run(fixed, balanced, layouts, kCompared);
  expect_clean(fixed);
  expect_clean(balanced);
}

// The paper's assignment on top of the strips ([balance] assignment = "heaviest-first", which
// only the wall file sets): the heaviest tile to the pipeserver that finishes first. Tiles
// change pipeservers, every pipeserver switching together, and the displays are still the static
// run's.
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
  // its tiles other pipeservers than the last frame did, and other pipeservers than the wall's
  // policy
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
  std::printf(
      "heaviest first: %d of %d frames from frame 2 on changed pipeservers, %d off the policy\n",
      changed, kFrames - 2, off_policy);
  EXPECT_GE(changed, 1);
  EXPECT_GE(off_policy, 1);

  std::vector<TileLayout> layouts;
  for (const LayoutMessage& line : lines) layouts.push_back(plan_from_message(wall, line));
  expect_displays_of_the_static_run(fixed, balanced, layouts, kCompared);
  expect_clean(fixed);
  expect_clean(balanced);
  fs::remove_all(dir);
}

// The compositing server places each tile where its message says, so the re-tiled frames
// compose there as on the emulator: alone (the displays of a static DVI run) and beside the
// DVI path (the two paths' displays identical, byte for byte, every frame).
TEST(LiveRunBalance, StripsRetileLiveOnTheVizserverPathToo) {
  std::vector<std::string> alone_args = kCommon;
  alone_args.insert(alone_args.end(), {"--balance", "strips", "--path", "vizserver"});
  std::vector<std::string> both_args = kCommon;
  both_args.insert(both_args.end(), {"--balance", "strips", "--path", "both", "--compare"});
  WallRun fixed("viz-balance-static", kCommon);
  WallRun alone("viz-balance-alone", alone_args);
  ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
  ASSERT_TRUE(alone.wait(120s).ok()) << alone.output();
  WallRun both("viz-balance-both", both_args);
  ASSERT_TRUE(both.wait(120s).ok()) << both.output();

  const Wall wall = default_wall();
  const std::vector<TileLayout> layouts = layouts_of(alone, wall);
  ASSERT_EQ(layouts.size(), static_cast<std::size_t>(kFrames));
  std::set<std::vector<Spot>> distinct;
  for (const TileLayout& l : layouts) distinct.insert(first_tiles_on(l, 0));
  EXPECT_GE(distinct.size(), 3u);  // it did re-tile
  expect_displays_of_the_static_run(fixed, alone, layouts, kCompared);
  // No strip is routed there, so none is counted as if it were.
  EXPECT_NE(alone.output().find("; strips routed per layout not counted: the vizserver path sends "
                                "whole tiles, no strips\nbalance: group swaps not checked: the "
                                "compositing server composes every frame from its own tiles\n"),
            std::string::npos)
      << alone.output();

  const std::string output = both.output();
  expect_no_mixed_swaps(output);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      output, m, std::regex("compare: (\\d+) display pictures identical byte for byte")))
      << output;
  EXPECT_GE(std::stoi(m[1].str()), kFrames * static_cast<int>(wall.displays.size()));
  expect_clean(fixed);
  expect_clean(alone);
  expect_clean(both);
}

// Resistance ([balance] resistance): a new layout is taken only when predicted to shorten the
// frame by that fraction. On 4 pipeservers no layout can be predicted to take less than a
// quarter of the frame (the slowest pipeserver has at least the mean of the work), so against a
// resistance of 0.8 every new cut is predicted to gain too little: the wall's own layout stays
// every frame, and the summary counts the cuts not taken. Beside it the same run without
// resistance re-tiles from frame 1 on (the even strips).
TEST(LiveRunBalance, ResistanceKeepsTheLayoutWhenTheGainIsBelowItAndWithoutItTheRunRetiles) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-resist-{}", getpid());
  fs::create_directories(dir);
  const fs::path wall_file =
      write_roomy_default_wall(dir, "\n[balance]\nmode = \"strips\"\nresistance = 0.8\n");
  const std::vector<std::string> common{
      "--scene", "strips",          "--frames", std::to_string(kFrames), "--refresh", "0", "--keep",
      "none",    "--ready-timeout", "5000",     "--stall-timeout",       "60000"};
  std::vector<std::string> resisting_args = common, free_args = common;
  resisting_args.insert(resisting_args.end(), {"--wall", wall_file.string()});
  free_args.insert(free_args.end(), {"--wall", wall_file.string(), "--resistance", "0"});
  WallRun resisting("resist-on", resisting_args);
  WallRun free_run("resist-off", free_args);
  ASSERT_TRUE(resisting.wait(120s).ok()) << resisting.output();
  ASSERT_TRUE(free_run.wait(120s).ok()) << free_run.output();
  fs::remove_all(dir);

  const std::string kept = resisting.output();
  EXPECT_NE(kept.find("balance strips: 1 layouts (from frames 0), strips"), std::string::npos)
      << kept;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(kept, m,
                                std::regex("\nbalance: (\\d+) new layouts? not taken \\(resistance "
                                           "0.8\\): the best was predicted to take ([0-9.]+) of "
                                           "the frame time\n")))
      << kept;
  // The steps from frame 2 to the last planned cuts other than the wall's own, all refused. A
  // step whose best cut is the wall's own (measured times that happen to favour it, on a busy
  // machine) has nothing to refuse, so not every step need count.
  EXPECT_GE(std::stoi(m[1].str()), 1);
  EXPECT_LE(std::stoi(m[1].str()), kFrames - 2);
  EXPECT_GE(std::stod(m[2].str()), 0.25);
  EXPECT_NE(slurp(resisting.out() / "summary.txt").find(m[0].str().substr(1)), std::string::npos);
  std::istringstream lines(slurp(resisting.out() / "layouts.txt"));
  std::set<std::string> tiles;  // each frame's LAYOUT line without its frame number
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count)
    tiles.insert(line.substr(line.find(' ', line.find(' ') + 1)));
  EXPECT_EQ(count, kFrames);
  EXPECT_EQ(tiles.size(), 1u);

  const std::string moved = free_run.output();
  ASSERT_TRUE(std::regex_search(moved, m, std::regex("balance strips: (\\d+) layouts \\(from")))
      << moved;
  EXPECT_GE(std::stoi(m[1].str()), 2);
  EXPECT_EQ(moved.find("not taken"), std::string::npos) << moved;
  expect_clean(resisting);
  expect_clean(free_run);
}

// On a tightly packed wall nearly every frame's plan is refused, and each refusal was a line of
// the planner's reason (200 to 300 characters) in the summary: 5 frames, 4 such lines. Here no
// strip fits (a strip is the display's width, a framebuffer half of it), so every plan from
// frame 1 on is refused: the first is given in full, the others counted.
TEST(LiveRunBalance, RefusedLayoutsAreCountedAfterTheFirst) {
  const fs::path wall = fs::temp_directory_path() / fmt::format("l2-refused-{}.toml", getpid());
  std::ofstream(wall) << "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 320\nheight = 240\n"
                         "[tiling]\nkind = \"grid\"\ntile_width = 160\ntile_height = 240\n"
                         "[pipeservers]\ncount = 2\nframebuffer_width = 200\n"
                         "framebuffer_height = 260\n";
  WallRun run("refused", {"--wall", wall.string(), "--balance", "strips", "--frames", "5",
                          "--refresh", "0", "--keep", "none"});
  const ExitStatus status = run.wait(60s);
  fs::remove(wall);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  std::vector<std::string> long_lines, refusals;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.size() > 160) long_lines.push_back(line);
    if (line.rfind("balance: not used, ", 0) == 0) refusals.push_back(line);
  }
  ASSERT_EQ(refusals.size(), 1u) << output;
  EXPECT_EQ(refusals.front().rfind("balance: not used, frame 1: ", 0), 0u) << output;
  EXPECT_LE(long_lines.size(), 1u) << output;
  EXPECT_NE(output.find("\nbalance: 3 more layouts refused, as above\n"), std::string::npos)
      << output;
  EXPECT_NE(slurp(run.out() / "summary.txt").find("\nbalance: 3 more layouts refused, as above\n"),
            std::string::npos);
  expect_clean(run);
}

}  // namespace
}  // namespace l2
