// `l2wall run` when things go wrong: a killed or hung pipeserver (and the report of the frames
// before it), a terminated run, line noise and a lost READY on the back-channel; what its stderr
// holds in a log file. Real processes, real ptys.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "l2wall/frame_stamp.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

// How soon after a fault the run must have ended, named it and cleaned up.
constexpr auto kFaultNoticeBound = 10s;

// What `tilelayout --wall WALL` prints on stdout and stderr, and its exit status.
std::pair<int, std::string> tilelayout_on(const fs::path& wall) {
  const Finished f = run_shell(fmt::format("'{}' --wall '{}'", TILELAYOUT_EXE, wall.string()), 60s);
  return {f.status.shell_code(), f.out};
}

// On both paths at once a frame shown stale would differ between them (older pixels on the DVI
// path, the background on the vizserver path): surviving a loss is refused there, not tried.
TEST(LiveRun, SurvivingAHostLossOnBothPathsIsRefusedBeforeAnythingStarts) {
  const fs::path wall = fs::temp_directory_path() / fmt::format("l2-survive-{}.toml", getpid());
  std::ofstream(wall) << "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 320\nheight = 240\n"
                         "[tiling]\nkind = \"grid\"\ntile_width = 160\ntile_height = 240\n"
                         "[pipeservers]\ncount = 2\nframebuffer_width = 400\n"
                         "framebuffer_height = 300\n[balance]\nmode = \"strips\"\n"
                         "survive_host_loss = true\n";
  WallRun run("survive-both", {"--frames", "3", "--wall", wall.string(), "--path", "both"});
  const ExitStatus status = run.wait(10s);
  fs::remove(wall);
  EXPECT_EQ(status.code, 1);
  EXPECT_EQ(run.output(), "l2wall: " + wall.string() +
                              ":14: balance.survive_host_loss: runs on --path dvi or vizserver, "
                              "not both (a frame shown stale differs between them: older pixels "
                              "on the DVI path, the background on the vizserver path)\n");
  EXPECT_FALSE(fs::exists(run.out() / "pipeserver-0.log")) << "a pipeserver was started";
  expect_clean(run);
}

TEST(LiveRun, PipeserverWithoutTilesIsRefusedBeforeAnythingStarts) {
  // One tile, two pipeservers: pipeserver 1 scanned out idle frames, never got READY, and the
  // run ended 11 s later with "pipeservers did not end after the last frame". tilelayout
  // printed the plan of that wall and exited 0.
  const fs::path wall = fs::temp_directory_path() / fmt::format("l2-idle-{}.toml", getpid());
  std::ofstream(wall) << "name = \"one tile, two pipeservers\"\n"
                         "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 320\nheight = 240\n"
                         "[tiling]\nkind = \"grid\"\ntile_width = 320\ntile_height = 240\n"
                         "[pipeservers]\ncount = 2\nframebuffer_width = 400\n"
                         "framebuffer_height = 300\n";
  WallRun run("idle", {"--frames", "3", "--wall", wall.string()});
  const ExitStatus status = run.wait(10s);
  const auto [tilelayout_status, tilelayout_out] = tilelayout_on(wall);
  fs::remove(wall);
  const std::string refusal = wall.string() +
                              ": pipeserver 1 gets no tiles (1 display tiles for 2 pipeservers); "
                              "every pipeserver needs a tile (one without scans out idle frames, "
                              "which never earn READY); what would fit, each alone: "
                              "pipeservers.count = 1; [tiling] tile_width = 320 with "
                              "tile_height = 210\n";
  EXPECT_EQ(status.code, 1);
  EXPECT_EQ(run.output(), "l2wall: " + refusal);
  EXPECT_EQ(tilelayout_status, 1);
  EXPECT_EQ(tilelayout_out, "tilelayout: " + refusal);
  EXPECT_FALSE(fs::exists(run.out() / "pipeserver-0.log")) << "a pipeserver was started";
  expect_clean(run);
}

TEST(LiveRun, WarnsOfWhatTilelayoutWarnsOf) {
  // The tiles leave the bottom 40 rows of the display uncovered: tilelayout said so, a run of
  // the same wall said nothing.
  const fs::path wall = fs::temp_directory_path() / fmt::format("l2-uncovered-{}.toml", getpid());
  std::ofstream(wall) << "name = \"uncovered rows\"\n"
                         "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 320\nheight = 240\n"
                         "[tiling]\nkind = \"list\"\ntiles = [[0, 0, 320, 200]]\n"
                         "[pipeservers]\ncount = 1\nframebuffer_width = 400\n"
                         "framebuffer_height = 300\n";
  WallRun run("uncovered", {"--frames", "1", "--wall", wall.string()});
  const ExitStatus status = run.wait(60s);
  const auto [tilelayout_status, tilelayout_out] = tilelayout_on(wall);
  fs::remove(wall);
  const std::string warning = wall.string() +
                              ": warning: canvas area 320x40 at 0,200 (display 0: 12800 pixels) "
                              "is not covered by any tile\n";
  EXPECT_EQ(status.code, 0) << run.output();
  EXPECT_NE(run.output().find("l2wall: " + warning), std::string::npos) << run.output();
  EXPECT_EQ(tilelayout_status, 0);
  EXPECT_NE(tilelayout_out.find("\n" + warning), std::string::npos) << tilelayout_out;
  expect_clean(run);
}

// The progress line redraws itself with \r: in a log file (or through mpirun) it was one line
// growing by a frame at every swap. Its stderr a file, a run prints none, without --no-progress.
TEST(LiveRun, NoProgressLineWhenStderrIsNotATerminal) {
  WallRun run("log-file", {"--frames", "5", "--refresh", "0", "--keep", "none"}, {}, false, "",
              true);
  const ExitStatus status = run.wait(60s);
  const std::string output = run.output();
  EXPECT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_EQ(output.find('\r'), std::string::npos) << output;
  EXPECT_EQ(output.find(" on the displays, "), std::string::npos) << output;
  EXPECT_NE(output.find("l2wall run: 5 frames on 4 displays"), std::string::npos) << output;
  expect_clean(run);
}

// A kept frame that could not be written ended the run with the error alone, and a summary.txt
// or report.csv that could not be written was left out without a word (exit 0).
TEST(LiveRun, KeptFrameThatCannotBeWrittenIsNamedWithWhatOutHolds) {
  WallRun run("keep-blocked", {"--frames", "3", "--keep", "every"},
              [](const fs::path& out) { std::ofstream(out / "frame-1") << "in the way"; });
  const ExitStatus status = run.wait(60s);
  EXPECT_EQ(status.code, 1);
  const std::string out = run.out().string();
  EXPECT_EQ(run.output(), "l2wall: " + out + "/frame-1: a file, not a folder; " + out +
                              " holds only part of this run: the frames kept before frame 1, no "
                              "summary.txt or report.csv of this run\n");
  EXPECT_TRUE(fs::exists(run.out() / "frame-0" / "display-0.png"));
  EXPECT_FALSE(fs::exists(run.out() / "summary.txt"));
  expect_clean(run);
}

TEST(LiveRun, SummaryThatCannotBeWrittenIsNamed) {
  WallRun run("summary-blocked", {"--frames", "2", "--keep", "none"},
              [](const fs::path& out) { fs::create_directories(out / "summary.txt"); });
  const ExitStatus status = run.wait(60s);
  EXPECT_EQ(status.code, 1);
  const std::string out = run.out().string();
  EXPECT_EQ(run.output(), "l2wall: " + out + "/summary.txt: cannot write: a folder, not a file; " +
                              out +
                              " holds only part of this run: report.csv, no summary.txt of "
                              "this run\n");
  expect_clean(run);
}

// A run a fault ended wrote no report.csv or summary.txt: what it had measured was lost. Now
// report.csv has a row for every frame that reached the displays before the fault (frames
// 0..K-1, each with its latency), and the summary's first line names the fault at frame K in
// the words of its line on stderr (`fault`: how that line starts, after "l2wall: ").
void expect_report_up_to_the_fault(const WallRun& run, const std::string& fault) {
  const std::string output = run.output();
  const auto at = output.find("l2wall: " + fault);
  ASSERT_NE(at, std::string::npos) << output;
  const std::string line = output.substr(at + 8, output.find('\n', at) - at - 8);
  const std::string summary = slurp(run.out() / "summary.txt");
  int k = -1;
  ASSERT_EQ(std::sscanf(summary.c_str(), "l2wall run: ended in a fault at frame %d: ", &k), 1)
      << summary;
  ASSERT_GE(k, 1) << summary;  // the pipeservers had rendered a few frames
  EXPECT_EQ(summary.substr(0, summary.find('\n')),
            fmt::format("l2wall run: ended in a fault at frame {}: {}", k, line));
  EXPECT_NE(summary.find(fmt::format("\nup to the fault: {} frames on 4 displays from 4 "
                                     "pipeservers in ",
                                     k)),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("\nlatency: 1 frame "), std::string::npos) << summary;
  const auto rows = read_csv(run.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(k) + 1) << summary;
  for (int f = 0; f < k; ++f) {
    const auto& row = rows[static_cast<std::size_t>(f) + 1];
    ASSERT_GE(row.size(), 6u) << "frame " << f;
    EXPECT_EQ(row[0], std::to_string(f));
    EXPECT_EQ(row[3], "1") << "frame " << f;  // latency
  }
}

TEST(LiveRun, KilledPipeserverIsNamedAndEverythingIsCleanedUp) {
  WallRun run("killed", {"--frames", "100000", "--refresh", "60"});
  const pid_t victim = running_pipeserver(run, 1);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const ExitStatus status = run.wait(20s);
  // About 0.4 s on a quiet machine; the bound leaves room for a CI machine loaded by two tests
  // of five processes each (7.9 s was seen with a sanitizer build running beside the suite).
  EXPECT_LT(std::chrono::steady_clock::now() - t0, kFaultNoticeBound);
  const std::string output = run.output();
  EXPECT_FALSE(status.ok());
  EXPECT_NE(output.find(fmt::format("pipeserver 1 (pid {}) killed by signal 9", victim)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("while rendering frame "), std::string::npos) << output;
  EXPECT_TRUE(fs::exists(run.out() / "fault" / "display-0.png")) << output;
  expect_report_up_to_the_fault(run,
                                fmt::format("pipeserver 1 (pid {}) killed by signal 9", victim));
  expect_clean(run);
}

TEST(LiveRun, HungPipeserverIsNamedWithinTheStallTimeout) {
  WallRun run("hung", {"--frames", "100000", "--refresh", "60", "--stall-timeout", "2000"});
  const pid_t victim = running_pipeserver(run, 2);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGSTOP), 0);
  // The run must end on its own (the stall timeout, 2 s, then the notice); waited for ten times
  // what that takes on an idle machine, as a loaded one stretches the notice and the teardown.
  // A run that ignored the stall timeout (the 60 s default, or none) fails here.
  const ExitStatus status = run.wait(10 * (2s + 500ms));
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(fmt::format("pipeserver 2 (pid {}) did not deliver frame", victim)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find(" (stopped by a signal); the other pipeservers are waiting for READY; "),
            std::string::npos)
      << output;
  expect_report_up_to_the_fault(run, "no display swap for 2000 ms: ");
  expect_clean(run);
}

// A stopped pipeserver when the other pipeservers give up first: they wait for READY (or SWAPPED)
// ready-timeout x (retries + 1), far less than the stall timeout here, and exit; the run named
// one of them ("exited with code 3 while rendering frame 841"), never the stopped one. It names
// the stopped one, and what the others were waiting for.
class StoppedPipeserver : public ::testing::TestWithParam<const char*> {};

// Pipeserver `pipeserver` once it has reported a few frames, found by its report file (the
// vizserver path has no links to find it by); its pid.
pid_t reporting_pipeserver(const WallRun& run, int pipeserver) {
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  const std::string report = fmt::format("pipeserver-{}.log", pipeserver);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.processes_naming(report);
    if (pids.size() == 1 && run.pipeserver_frames_logged(pipeserver) >= 3) return pids.front();
    std::this_thread::sleep_for(20ms);
  }
  return -1;
}

TEST_P(StoppedPipeserver, IsNamedNotTheHostsThatGaveUpWaitingForIt) {
  const std::string path = GetParam();
  WallRun run("stopped-" + path, {"--frames", "100000", "--refresh", "0", "--path", path,
                                  "--ready-timeout", "500", "--stall-timeout", "60000"});
  const pid_t victim = reporting_pipeserver(run, 2);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGSTOP), 0);
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(fmt::format("l2wall: pipeserver 2 (pid {}) stopped answering (stopped by "
                                    "a signal): it did not deliver frame ",
                                    victim)),
            std::string::npos)
      << output;
  const std::string waiting = path == "vizserver"
                                  ? "gave up waiting for SWAPPED from the compositing server"
                                  : "gave up waiting for READY";
  EXPECT_NE(output.find(waiting), std::string::npos) << output;
  EXPECT_EQ(output.find("while rendering frame"), std::string::npos) << output;
  expect_clean(run);  // a stopped process still ends on SIGKILL
}

INSTANTIATE_TEST_SUITE_P(Paths, StoppedPipeserver, ::testing::Values("dvi", "vizserver", "both"));

// The stall clock ran from the start of a swap's work (comparing, keeping pictures, the
// compositing server's frame), so a swap whose work took longer than the stall timeout ended
// the run: "no display swap ... did not deliver frame 10" of a 10-frame run, on a loaded
// machine. Keeping the only frame takes longer than 1 ms; the run has nothing left to wait for.
TEST(LiveRun, ASlowLastSwapIsNotAStall) {
  WallRun run("slow-last-swap",
              {"--frames", "1", "--refresh", "0", "--keep", "every", "--stall-timeout", "1"});
  const ExitStatus status = run.wait(60s);
  const std::string output = run.output();
  EXPECT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_EQ(output.find("no display swap"), std::string::npos) << output;
  EXPECT_TRUE(fs::exists(run.out() / "frame-0" / "wall.png")) << output;
  expect_clean(run);
}

// The frames a stopped run showed, from its summary's first line ("l2wall run: N frames ...");
// -1 without one.
int summary_frames(const WallRun& run) {
  const std::string summary = slurp(run.out() / "summary.txt");
  int frames = -1;
  return std::sscanf(summary.c_str(), "l2wall run: %d frames", &frames) == 1 ? frames : -1;
}

// A run a signal stopped after `frames` frames: its report covers exactly those, the last one
// is kept (--keep last), the summary says what limited it.
void expect_report_of_stopped_run(const WallRun& run, int frames) {
  EXPECT_EQ(read_csv(run.out() / "report.csv").size(), static_cast<std::size_t>(frames) + 1);
  EXPECT_TRUE(fs::exists(run.out() / fmt::format("frame-{}", frames - 1) / "wall.png"));
  EXPECT_NE(slurp(run.out() / "summary.txt").find("\nlimited by "), std::string::npos);
}

// SIGTERM to l2wall alone ends the run as q does (stop_signal.hpp): exit 128 + 15.
TEST(LiveRun, TerminatedRunEndsItsHostsAndRemovesTheirLinks) {
  WallRun run("sigterm", {"--frames", "100000", "--refresh", "60"});
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();
  ASSERT_EQ(kill(run.pid(), SIGTERM), 0);
  const ExitStatus status = run.wait(10s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 143) << output;
  const int frames = summary_frames(run);
  ASSERT_GE(frames, 1) << output;  // the pipeserver had published frame 2: frame 0 was shown
  EXPECT_NE(output.find(fmt::format("l2wall: stopped by signal 15 (Terminated) after {} frames; "
                                    "report: {}\n",
                                    frames, run.out().string())),
            std::string::npos)
      << output;
  expect_report_of_stopped_run(run, frames);
  expect_clean(run);
}

// Ctrl-C: the terminal sends SIGINT to its whole foreground process group, l2wall and every
// pipeserver at once. The run ends as q does: exit 130, the frames shown are the run, summary
// and report written, nothing of the session left running.
TEST(LiveRun, CtrlCEndsTheRunAsQDoesWithItsReport) {
  WallRun run("sigint", {"--frames", "100000", "--refresh", "60"}, {}, true);
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();
  ASSERT_EQ(kill(-run.pid(), SIGINT), 0);  // the group l2wall leads
  const ExitStatus status = run.wait(20s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 130) << status.describe() << "\n" << output;
  const int frames = summary_frames(run);
  ASSERT_GE(frames, 1) << output;
  EXPECT_NE(output.find(fmt::format("l2wall: stopped by signal 2 (Interrupt) after {} frames; "
                                    "report: {}\n",
                                    frames, run.out().string())),
            std::string::npos)
      << output;
  expect_report_of_stopped_run(run, frames);
  expect_clean(run);
  // pgrep: no process of the session l2wall led is left (exit status 1: none matched).
  const Finished pgrep = run_shell(fmt::format("pgrep -s {}", run.pid()), 10s);
  EXPECT_EQ(pgrep.status.shell_code(), 1);
  EXPECT_EQ(pgrep.out, "") << "left in the session";
}

// l2wall itself killed (no chance to stop anyone): the pipeservers see their back-channel hang
// up and their compositing-server connection close, the compositing server sees l2wall's display
// stream close; all end on their own and the pipeservers remove their links.
TEST(LiveRun, KilledRunLeavesNoProcessAndNoLink) {
  WallRun run("sigkill", {"--frames", "100000", "--refresh", "60", "--path", "both"});
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();
  ASSERT_EQ(run.vizservers().size(), 1u) << run.output();
  ASSERT_EQ(kill(run.pid(), SIGKILL), 0);
  EXPECT_EQ(run.wait(10s).signal, SIGKILL);
  const auto deadline = std::chrono::steady_clock::now() + kFaultNoticeBound;
  while ((!run.processes_naming("").empty() || !run.leftover_segments().empty()) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  expect_clean(run);
}

TEST(LiveRun, PathMismatchWritesBothPicturesAndADiffAndFails) {
  WallRun run("mismatch", {"--frames", "5", "--refresh", "0", "--path", "both", "--compare",
                           "--inject-mismatch", "2"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find("frame 2: display 0 differs between the DVI and vizserver paths in 1 "
                        "pixels"),
            std::string::npos)
      << output;
  const fs::path dir = run.out() / "mismatch-frame-2";
  const RgbImage dvi = read_png(dir / "display-0-dvi.png");
  const RgbImage viz = read_png(dir / "display-0-vizserver.png");
  const RgbImage diff = read_png(dir / "display-0-diff.png");
  int differing = 0, marked = 0;
  for (int y = 0; y < dvi.height(); ++y) {
    for (int x = 0; x < dvi.width(); ++x) {
      differing += !(dvi.at(x, y) == viz.at(x, y));
      marked += !(diff.at(x, y) == Rgb{});
    }
  }
  EXPECT_EQ(differing, 1);
  EXPECT_EQ(marked, 1);
  EXPECT_EQ(diff.at(dvi.width() / 2, dvi.height() / 2), (Rgb{128, 0, 0}));
  expect_clean(run);
}

TEST(LiveRun, LineNoiseAndADroppedReadyAreRecovered) {
  WallRun run("noise", {"--frames", "6", "--refresh", "0", "--inject-noise", "1", "--drop-ready",
                        "3", "--ready-timeout", "200"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("1 READY dropped"), std::string::npos) << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  for (int i = 0; i < 4; ++i) {
    const auto at = output.find(fmt::format("back-channel pipeserver {}: resyncs ", i));
    ASSERT_NE(at, std::string::npos) << output;
    int resyncs = 0, noise = 0, sync_sent = 0;
    ASSERT_EQ(std::sscanf(output.c_str() + at,
                          "back-channel pipeserver %*d: resyncs %d noise_bytes %d sync_sent %d",
                          &resyncs, &noise, &sync_sent),
              3)
        << output.substr(at, 80);
    EXPECT_GT(resyncs, 0) << "pipeserver " << i;
    EXPECT_GT(noise, 0) << "pipeserver " << i;
    if (i == 0) {
      EXPECT_GE(sync_sent, 1);
    }
  }
  expect_clean(run);
}

}  // namespace
}  // namespace l2
