// What a live run of a wall with [displays] says about frame lock (docs/wall-file.md): the
// summary's count of mismatched refreshes and frame-lock.csv, read back and checked against the
// example walls' clocks (examples/walls/projectors-*.toml: three projectors in one swap group at
// 0, +20000 and -150000 ppm), on one machine and under MPI alike.
#pragma once

#include <gtest/gtest.h>

#include <regex>

#include "wall_run.hpp"

namespace l2::testing_support {

inline const fs::path kFrameLockWalls = fs::path(L2_SOURCE_DIR) / "examples" / "walls";

struct FrameLockRun {
  std::uint64_t refreshes = 0, mismatched = 0;  // from the summary line
  std::vector<std::vector<std::string>> csv;    // frame-lock.csv, header first
  // Of the kept frames (--keep every): those whose frame-lock.txt has a projector showing the
  // frame before the folder's (frame stamp K-1 in frame-K), those with one not showing the
  // folder's frame at all (the older frame, or none yet), and those without the file.
  int saved_older = 0, saved_not_own = 0, saved_without_file = 0;
};

// Kept frame K's frame-lock.txt: which frame each projector showed at the refresh K swapped in.
inline void count_saved_stamps(const fs::path& out, int frames, FrameLockRun& r) {
  for (int k = 0; k < frames; ++k) {
    const fs::path file = out / fmt::format("frame-{}", k) / "frame-lock.txt";
    if (!fs::exists(file)) {
      ++r.saved_without_file;
      continue;
    }
    const std::string text = slurp(file);
    bool older = false, not_own = false;
    for (int d = 0; d < 3; ++d) {
      older |=
          k > 0 && text.find(fmt::format("display {}: frame {},", d, k - 1)) != std::string::npos;
      not_own |= text.find(fmt::format("display {}: frame {},", d, k)) == std::string::npos;
    }
    r.saved_older += older;
    r.saved_not_own += not_own;
  }
}

// `frames`: the run's, each kept (--keep every).
inline FrameLockRun frame_lock_of(const WallRun& run, int frames) {
  FrameLockRun r;
  std::smatch m;
  const std::string out = run.output();
  const std::regex line(
      R"(frame lock: [^\n]*mismatched refreshes [^\n]* of (\d+): group 0: (\d+);)");
  EXPECT_TRUE(std::regex_search(out, m, line)) << out;
  if (m.size() == 3) {
    r.refreshes = std::stoull(m[1]);
    r.mismatched = std::stoull(m[2]);
  }
  r.csv = read_csv(run.out() / "frame-lock.csv");
  count_saved_stamps(run.out(), frames, r);
  return r;
}

// The frame counter of a display at `ppm` at house refresh s: its last retrace, floor(s·r).
inline long long frame_counter(long long s, long long ppm) {
  return s * (1000000 + ppm) / 1000000;
}

// projectors-drifting.toml's run: mismatched refreshes, every one the slow projector's showing
// the frame before the others'.
inline void expect_free_running(const FrameLockRun& r) {
  EXPECT_GT(r.mismatched, 0u);
  EXPECT_EQ(r.saved_without_file, 0);
  // A kept frame is saved at the refresh it swapped in, where the slow projector may still show
  // the frame before: the visible proof, as many as the mismatched refreshes at most.
  EXPECT_GT(r.saved_older, 0);
  EXPECT_LE(static_cast<std::uint64_t>(r.saved_older), r.mismatched);
  ASSERT_EQ(r.csv.size(), r.refreshes + 1);
  EXPECT_EQ(r.csv[0],
            (std::vector<std::string>{"refresh", "counter_0", "frame_0", "counter_1", "frame_1",
                                      "counter_2", "frame_2", "mismatched_groups"}));
  std::uint64_t rows_mismatched = 0, slow_behind = 0;
  for (std::size_t i = 1; i < r.csv.size(); ++i) {
    const auto& row = r.csv[i];
    ASSERT_GE(row.size(), 7u) << i;
    const long long s = std::stoll(row[0]);
    EXPECT_EQ(s, static_cast<long long>(i - 1));
    EXPECT_EQ(std::stoll(row[1]), frame_counter(s, 0));
    EXPECT_EQ(std::stoll(row[3]), frame_counter(s, 20000));
    EXPECT_EQ(std::stoll(row[5]), frame_counter(s, -150000));
    const bool mismatched = row.size() == 8 && row[7] == "0";
    rows_mismatched += mismatched;
    if (mismatched && std::stoi(row[6]) < std::stoi(row[2])) ++slow_behind;
    if (!mismatched) {
      EXPECT_TRUE(row[2] == row[6] || row[6] == "-1" || row[2] == "-1") << i;
    }
    EXPECT_EQ(row[2], row[4]) << "the faster projector is never behind, refresh " << s;
  }
  EXPECT_EQ(rows_mismatched, r.mismatched);
  EXPECT_EQ(slow_behind, r.mismatched);
}

// projectors-house-sync.toml's run: every counter the house refresh, every frame the same.
inline void expect_house_sync(const FrameLockRun& r) {
  EXPECT_EQ(r.mismatched, 0u);
  EXPECT_EQ(r.saved_without_file, 0);
  EXPECT_EQ(r.saved_not_own, 0);
  ASSERT_EQ(r.csv.size(), r.refreshes + 1);
  for (std::size_t i = 1; i < r.csv.size(); ++i) {
    const auto& row = r.csv[i];
    ASSERT_GE(row.size(), 7u) << i;
    for (const std::size_t c : {1u, 3u, 5u}) EXPECT_EQ(row[c], row[0]) << i;
    EXPECT_EQ(row[2], row[4]) << i;
    EXPECT_EQ(row[2], row[6]) << i;
    EXPECT_EQ(row.size(), 7u) << "no group mismatched, refresh " << row[0];
  }
}

}  // namespace l2::testing_support
