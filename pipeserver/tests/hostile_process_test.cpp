// The hostile files of hostile_files.hpp through the pipeserver program, as a user meets them:
// each ends the process with exit code 1 and one line on stderr naming the file, not a signal
// (a stack overflow is SIGSEGV), not a hang, and without memory out of proportion to the file:
// its peak stays within a margin of a pipeserver refusing a file that claims nothing.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pipeserver/hostile_files.hpp"

extern char** environ;

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// What a pipeserver did: its exit code (-signal when a signal ended it, -1000 when it overstayed
// and was killed), its stderr and stdout, its peak memory.
struct Ended {
  int code = 0;
  std::string output;
  long peak_kib = 0;
};

Ended run_pipeserver(std::vector<std::string> args, const fs::path& output) {
  args.insert(args.begin(), PIPESERVER_EXE);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 2, 1);
  Ended e;
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Far above what any refusal takes, on a loaded machine or under ASan: only a hang overstays
  // it.
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      e.code = -1000;
      break;
    }
    std::this_thread::sleep_for(10ms);
  }
  if (e.code == 0) e.code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  e.peak_kib = usage.ru_maxrss;
  std::ifstream in(output);
  e.output.assign(std::istreambuf_iterator<char>(in), {});
  return e;
}

class HostileProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("l2_hostile_process_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes) const {
    hostile::write(dir_ / name, bytes);
    return dir_ / name;
  }
  Ended refuse(const std::vector<std::string>& args) const {
    std::vector<std::string> all = args;
    all.insert(all.end(), {"--out", (dir_ / "out").string()});
    return run_pipeserver(all, dir_ / "output.txt");
  }
  // Each file through `option` (after `before`): exit 1, one line naming the file, the peak
  // within `margin_kib` of the baseline file's.
  void expect_refused(const std::vector<std::string>& before, const std::string& option,
                      const fs::path& baseline_file,
                      const std::vector<std::pair<std::string, std::string>>& files) const {
    std::vector<std::string> args = before;
    args.insert(args.end(), {option, baseline_file.string()});
    const Ended baseline = refuse(args);
    ASSERT_EQ(baseline.code, 1) << baseline.output;
    for (const auto& [name, bytes] : files) {
      const fs::path f = file(name, bytes);
      args.back() = f.string();
      const Ended e = refuse(args);
      EXPECT_EQ(e.code, 1) << name << ": " << e.output;
      EXPECT_EQ(e.output.rfind("pipeserver: " + f.string() + ": ", 0), 0u) << e.output;
      EXPECT_EQ(e.output.find('\n'), e.output.size() - 1) << e.output;
      // A margin for what reading a file of a few bytes to a few MB takes; what the files claim
      // is gigabytes.
      EXPECT_LT(e.peak_kib, baseline.peak_kib + 100 * 1024) << name;
    }
  }
  fs::path dir_;
};

TEST_F(HostileProcess, ModelsAreRefusedInOneLine) {
  const std::string ply = hostile::ply_header("ascii") + hostile::kPlyAsciiBody;
  expect_refused({}, "--mesh", file("baseline.stl", "solid"),
                 {{"deep.gltf", hostile::gltf(hostile::node_chain(20000))},
                  {"twice.gltf", hostile::gltf(hostile::node_diamonds(40))},
                  {"json.gltf", hostile::gltf(hostile::node_chain(1),
                                              ", \"extras\": " + hostile::nested_arrays(1000000))},
                  {"big.glb", hostile::glb(0xFFFFFFF0u)},
                  {"deep.dae", hostile::collada_chain(17400)},
                  {"deep.x", hostile::x_frame_chain(20000)},
                  {"cut21.ply", ply.substr(0, 21)},
                  {"cut60.ply", ply.substr(0, 60)},
                  {"cut-end.ply", ply.substr(0, ply.find("end_header") + 4)},
                  {"list.ply", hostile::binary_ply_list(100000000)},
                  {"list-ascii.ply",
                   hostile::ply_header("ascii", "uint") + "0 0 0\n1 0 0\n0 1 0\n4000000000\n"},
                  {"counts.off", "OFF\n1000000000 1000000000 0\n0 0 0\n"},
                  {"nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"}});
}

TEST_F(HostileProcess, PicturesAreRefusedInOneLine) {
  const std::string small = hostile::small_png();
  expect_refused({"--scene", "picture"}, "--content", file("baseline.png", "not a picture\n"),
                 {{"huge.png", hostile::png(100000, 100000, false, std::string(8, '\0'))},
                  {"huge-interlaced.png", hostile::png(100000, 100000, true, std::string(8, '\0'))},
                  {"cut.png", small.substr(0, small.size() / 2)},
                  {"text.jpg", "not a picture\n"},
                  {"bad.jpg", std::string("\xff\xd8\xff\xe0", 4) + std::string(60, 'x')},
                  // Headers OpenImageIO believed (issue 54): aborts, a hang, gigabytes.
                  {"wide.ppm", hostile::pnm_wide(2000000000)},
                  {"wide.pfm", hostile::pfm_wide(2000000000)},
                  {"tall.ppm", hostile::pnm_wide(1000000)},
                  {"huge.jpg", hostile::jpeg_frame(65500, 65500)},
                  {"huge.gif", hostile::gif_screen(16384, 16384)},
                  {"levels.dds", hostile::dds_levels(0xFFFFFFFFu)}});
}

}  // namespace
}  // namespace l2
