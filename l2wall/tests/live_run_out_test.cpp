// `l2wall run --out` on a file system that is read-only or fills up during the run: a tmpfs in a
// mount namespace of the run's own (unshare -m). Refused before any pipeserver starts, or ended
// in one line naming the file, the system's reason and what OUT holds; every picture there is
// whole. A read-only OUT was found by the pipeservers (one line in std::filesystem's words), and
// OpenImageIO's PNG writer lost ENOSPC: pictures were left empty or cut short under their names
// and the run went on.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

// Whether this machine lets a test mount a tmpfs in a mount namespace of its own (root, or a
// container that allows it).
bool can_mount(const fs::path& dir) {
  fs::create_directories(dir);
  const Finished probe = run_shell(
      fmt::format("unshare -m sh -c 'mount -t tmpfs tmpfs \"$0\"' '{}'", dir.string()), 30s);
  fs::remove_all(dir);
  return probe.status.ok();
}

// A run of `name` whose --out is a tmpfs mounted with `options` in a mount namespace of its own.
// A `sleep` started in that namespace keeps it (and the tmpfs) after l2wall ends, so the test
// reads what the run left through /proc/<sleep>/root; its pid goes to OUT.keeper.
class RunOnTmpfs {
 public:
  RunOnTmpfs(const std::string& name, const std::string& options,
             const std::vector<std::string>& args)
      : out_(WallRun::folder_for(name) / "out"),
        run_(name, args, {}, false,
             fmt::format("unshare -m sh -c 'mount -t tmpfs -o \"$1\" tmpfs \"$0\" || exit 77; "
                         "sleep 300 </dev/null >/dev/null 2>&1 & echo $! > \"$0.keeper\"; shift; "
                         "exec \"$@\"' '{}' '{}'",
                         out_.string(), options)) {}
  ~RunOnTmpfs() {
    if (const pid_t keeper = keeper_pid(); keeper > 0) kill(keeper, SIGKILL);
  }
  WallRun& run() { return run_; }
  // `relative` in OUT as the run saw it.
  fs::path seen(const fs::path& relative) const {
    return fs::path(fmt::format("/proc/{}/root", keeper_pid())) / out_.relative_path() / relative;
  }
  // The files in OUT as the run saw them, with their paths in OUT, sorted.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    const fs::path root = seen("");
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.is_regular_file()) names.push_back(e.path().lexically_relative(root).string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  pid_t keeper_pid() const {
    const std::string text = slurp(out_.string() + ".keeper");
    return text.empty() ? -1 : std::stoi(text);
  }
  fs::path out_;
  WallRun run_;
};

#define SKIP_WITHOUT_MOUNTS()                         \
  if (!can_mount(WallRun::folder_for("mount-probe"))) \
  GTEST_SKIP() << "no tmpfs in a mount namespace here (unshare -m and mount need root)"

TEST(OutFolder, ReadOnlyIsRefusedBeforeAnyPipeserverStarts) {
  SKIP_WITHOUT_MOUNTS();
  RunOnTmpfs on("read-only", "ro", {"--frames", "3", "--keep", "every"});
  WallRun& run = on.run();
  const ExitStatus status = run.wait(60s);
  EXPECT_EQ(status.code, 1) << status.describe();
  EXPECT_EQ(run.output(), "l2wall: --out " + run.out().string() +
                              ": cannot write into the folder: Read-only file system\n");
  EXPECT_TRUE(on.files().empty());
  expect_clean(run);
}

// What OUT holds when frame `k`'s pictures could not all be written, as the run says it: the
// frames kept before it, and those of its pictures that were written.
std::string held_at(int k, const std::vector<std::string>& files) {
  std::vector<std::string> held, part;
  if (k > 0) held.push_back(fmt::format("the frames kept before frame {}", k));
  const std::string folder = fmt::format("frame-{}/", k);
  for (const std::string& f : files) {
    if (f.rfind(folder, 0) == 0) part.push_back(f.substr(folder.size()));
  }
  if (!part.empty()) held.push_back(fmt::format("{} of frame {}", fmt::join(part, ", "), k));
  return fmt::format("{}", fmt::join(held, ", "));
}

// Every frame kept (a picture of each display and of the wall) does not fit in 200 KiB: the run
// ends at the first picture that does not fit, wherever that is; what is there is whole.
TEST(OutFolder, FullEndsTheRunAtThePictureThatDoesNotFitEveryPictureThereWhole) {
  SKIP_WITHOUT_MOUNTS();
  RunOnTmpfs on("full", "size=200k", {"--frames", "10", "--keep", "every"});
  WallRun& run = on.run();
  const ExitStatus status = run.wait(60s);
  EXPECT_EQ(status.code, 1) << status.describe();
  const std::string out = run.out().string(), output = run.output();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m, std::regex("/frame-([0-9]+)/([^/:]+): cannot write")))
      << output;
  const int k = std::stoi(m[1]);
  const std::string failed = fmt::format("frame-{}/{}", k, m[2].str());
  const std::vector<std::string> files = on.files();
  const std::string held = held_at(k, files);
  EXPECT_EQ(output,
            fmt::format("l2wall: {}/{}: cannot write: No space left on device{}\n", out, failed,
                        held.empty() ? ""
                                     : fmt::format("; {} holds only part of this run: "
                                                   "{}, no summary.txt or report.csv of "
                                                   "this run",
                                                   out, held)));
  // Each frame before it whole, then what frame k holds, and the pipeservers' logs: nothing cut
  // short, no summary.txt or report.csv, nothing left of the picture that did not fit.
  for (const std::string& f : files) {
    if (f.ends_with(".png")) {
      EXPECT_NO_THROW(read_png(on.seen(f))) << f;
    } else {
      EXPECT_TRUE(f.rfind("pipeserver-", 0) == 0 && f.ends_with(".log")) << f;
    }
    EXPECT_EQ(f.find(failed), std::string::npos) << f;
  }
  for (int before = 0; before < k; ++before) {
    for (const std::string name :
         {"display-0.png", "display-1.png", "display-2.png", "display-3.png", "wall.png"}) {
      const std::string f = fmt::format("frame-{}/{}", before, name);
      EXPECT_NE(std::find(files.begin(), files.end(), f), files.end()) << f;
    }
  }
  expect_clean(run);
}

// 20 KiB hold the four pipeservers' logs and report.csv (a page each) but not summary.txt; 16 KiB
// not report.csv either.
TEST(OutFolder, FullAtTheReportSaysWhatOutHolds) {
  SKIP_WITHOUT_MOUNTS();
  const std::vector<std::string> args = {"--frames", "10", "--keep", "none"};
  RunOnTmpfs summary_on("full-summary", "size=20k", args),
      report_on("full-report", "size=16k", args);
  for (RunOnTmpfs* on : {&summary_on, &report_on}) {
    const ExitStatus status = on->run().wait(60s);
    EXPECT_EQ(status.code, 1) << status.describe();
  }
  const std::string out = summary_on.run().out().string();
  EXPECT_EQ(summary_on.run().output(),
            "l2wall: " + out + "/summary.txt: cannot write: No space left on device; " + out +
                " holds only part of this run: report.csv, no summary.txt of this run\n");
  EXPECT_EQ(summary_on.files(),
            (std::vector<std::string>{"pipeserver-0.log", "pipeserver-1.log", "pipeserver-2.log",
                                      "pipeserver-3.log", "report.csv"}));
  EXPECT_EQ(read_csv(summary_on.seen("report.csv")).size(), 11u);  // a header and 10 frames
  EXPECT_EQ(report_on.run().output(), "l2wall: " + report_on.run().out().string() +
                                          "/report.csv: cannot write: No space left on device\n");
  EXPECT_EQ(report_on.files().size(), 4u);  // the pipeservers' logs
  expect_clean(summary_on.run());
  expect_clean(report_on.run());
}

}  // namespace
}  // namespace l2
