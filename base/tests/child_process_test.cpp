#include "base/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace l2 {
namespace {

using namespace std::chrono_literals;

bool process_exists(pid_t pid) {
  return kill(pid, 0) == 0;
}

// True once the process ignores SIGTERM: bit 15 of the SigIgn mask in /proc/PID/status.
bool ignores_sigterm(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("SigIgn:", 0) == 0) {
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1) & 1) != 0;
    }
  }
  return false;
}

// A shell that ignores SIGTERM, returned once it does: a SIGTERM sent before its trap was set
// would end it, and the test would fail for the wrong reason.
ChildProcess stubborn_child() {
  ChildProcess p({"/bin/sh", "-c", "trap '' TERM; while :; do sleep 0.05; done"});
  const auto give_up = std::chrono::steady_clock::now() + 5s;
  while (!ignores_sigterm(p.pid()) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_TRUE(ignores_sigterm(p.pid())) << "the shell did not set its trap within 5 s";
  return p;
}

TEST(ChildProcess, ReportsExitCode) {
  ChildProcess p({"/bin/sh", "-c", "exit 3"});
  const auto status = p.wait_for(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(status->code, 3);
  EXPECT_FALSE(status->ok());
  EXPECT_EQ(status->describe(), "exited with code 3");
}

TEST(ChildProcess, PollDoesNotBlockWhileRunning) {
  ChildProcess p({"/bin/sleep", "5"});
  EXPECT_FALSE(p.poll());
  EXPECT_TRUE(process_exists(p.pid()));
}

TEST(ChildProcess, TerminateEndsAndReapsAStubbornChild) {
  // The child ignores SIGTERM, so only the SIGKILL after the grace period ends it.
  ChildProcess p = stubborn_child();
  const pid_t pid = p.pid();
  const ExitStatus s = p.terminate(200ms);
  EXPECT_EQ(s.signal, SIGKILL);
  EXPECT_EQ(s.describe(), "killed by signal 9 (Killed)");
  EXPECT_FALSE(process_exists(pid));  // reaped: not even a zombie
}

TEST(ChildProcess, RequestStopAsksWithoutWaiting) {
  // A child that ignores SIGTERM: a request_stop that waited for the end (as terminate does)
  // would return only after a grace period, or leave it ended.
  ChildProcess p = stubborn_child();
  p.request_stop();
  EXPECT_FALSE(p.poll()) << "request_stop waited for, or forced, the end";
  EXPECT_TRUE(process_exists(p.pid()));
  EXPECT_EQ(p.terminate(200ms).signal, SIGKILL);
  p.request_stop();  // after it ended and was reaped: its pid may be reused, nothing is sent
}

TEST(ChildProcess, DestructorLeavesNoOrphan) {
  pid_t pid = 0;
  {
    ChildProcess p({"/bin/sleep", "30"});
    pid = p.pid();
    ASSERT_TRUE(process_exists(pid));
  }
  EXPECT_FALSE(process_exists(pid));
}

TEST(ChildProcess, MissingProgramIsAClearError) {
  try {
    ChildProcess p({"/nonexistent/pipeserver"});
    // posix_spawn may report ENOENT through the child's exit code 127 instead.
    const auto s = p.wait_for(5s);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->code, 127);
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot start /nonexistent/pipeserver: No such file or directory");
  }
}

TEST(ChildProcess, ExtraEnvironmentIsAddedAndReplacesAVariableOfTheSameName) {
  const auto out = std::filesystem::temp_directory_path() / "l2-child-env.txt";
  ::setenv("L2_CHILD_TEST_A", "from the parent", 1);
  ChildProcess p(
      {"/bin/sh", "-c",
       "printf '%s|%s|%s' \"$L2_CHILD_TEST_A\" \"$L2_CHILD_TEST_B\" \"$PATH\" > " + out.string()},
      {"L2_CHILD_TEST_A=replaced", "L2_CHILD_TEST_B=added"});
  ::unsetenv("L2_CHILD_TEST_A");
  ASSERT_TRUE(p.wait_for(5s));
  std::ifstream in(out);
  std::string got;
  std::getline(in, got);
  EXPECT_EQ(got, std::string("replaced|added|") + std::getenv("PATH"));  // the rest inherited
  std::filesystem::remove(out);
}

TEST(ChildProcess, CapturedLinesArriveInOrderPerStream) {
  ChildProcess p({"/bin/sh", "-c", "echo one; echo two >&2; echo three; printf four"}, {},
                 Capture{true, true});
  EXPECT_EQ(p.read_line(Stream::Err, 5s), "two");
  EXPECT_EQ(p.read_line(Stream::Out, 5s), "one");
  EXPECT_EQ(p.read_line(Stream::Out, 5s), "three");
  const Finished f = p.finish(5s);
  EXPECT_EQ(f.out, "four");  // the unfinished last line is in what is left
  EXPECT_EQ(f.err, "");
  EXPECT_EQ(f.status.describe(), "exited with code 0");
  EXPECT_FALSE(f.killed);
}

TEST(ChildProcess, ReadLineGivesUpAtTheDeadlineAndAtTheEnd) {
  ChildProcess quiet({"/bin/sleep", "5"}, {}, Capture{true, false});
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(quiet.read_line(Stream::Out, 100ms), std::nullopt);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
  ChildProcess done({"/bin/true"}, {}, Capture{true, false});
  EXPECT_EQ(done.read_line(Stream::Out, 5s), std::nullopt);  // closed without a line
}

TEST(ChildProcess, FinishKillsAChildThatOverstays) {
  const Finished f = run({"/bin/sh", "-c", "echo started; exec sleep 30"}, 300ms);
  EXPECT_TRUE(f.killed);
  EXPECT_EQ(f.status.shell_code(), 128 + SIGKILL);
  EXPECT_EQ(f.out, "started\n");
}

TEST(ChildProcess, RunFindsAProgramInPath) {
  const Finished f = run({"sh", "-c", "echo $0"}, 5s);
  EXPECT_EQ(f.status.shell_code(), 0);
  EXPECT_EQ(f.out, "sh\n");
}

TEST(ChildProcess, RunShellJoinsStderrToStdoutInOrder) {
  const Finished f = run_shell("echo out; echo err >&2; exit 4", 5s);
  EXPECT_EQ(f.out, "out\nerr\n");
  EXPECT_EQ(f.status.shell_code(), 4);
}

}  // namespace
}  // namespace l2
