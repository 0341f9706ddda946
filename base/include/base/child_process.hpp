// A child process: started with posix_spawnp, watched without blocking, its stdout and stderr
// optionally captured and read line by line with a deadline, and always reaped — an owner that
// ends for any reason leaves no orphan behind. Every wait is bounded.
//
// Example:
//
//   using namespace std::chrono_literals;
//   l2::ChildProcess server({"vizserver", "--displays", "640x480", "--pipeservers", "1",
//                            "--viz-port", "0", "--frames", "1", "--out", "out/viz"},
//                           {}, l2::Capture{.out = true});
//   const std::string listening = server.read_line(l2::Stream::Out, 5000ms).value_or("");
//   ...  // "listening on 127.0.0.1:PORT": connect, send the frame
//   std::optional<l2::ExitStatus> status = server.wait_for(10s);
//   if (!status) status = server.terminate();  // SIGTERM, SIGKILL after 500 ms; reaped
//   if (!status->ok()) fmt::print(stderr, "vizserver {}\n", status->describe());
//
//   const l2::Finished f = l2::run_shell("strip_headers decode 629400f00a01", 2min);
//   // f.status.shell_code() is the shell's $?, f.out both streams
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "base/fd.hpp"

namespace l2 {

struct ExitStatus {
  int code = 0;    // exit code when the process exited
  int signal = 0;  // terminating signal, 0 if it exited
  // A process elsewhere (an MPI rank) seen to end without its status: its connection closed.
  bool gone = false;
  std::string gone_how;  // how it was found gone, "is lost (...)"; empty: its connection closed
  bool ok() const { return !gone && signal == 0 && code == 0; }
  // What a shell's $? shows: the exit code, or 128 + the signal.
  int shell_code() const { return signal != 0 ? 128 + signal : code; }
  // "exited with code 3" / "killed by signal 9 (Killed)" / "is gone (its connection ...)"
  std::string describe() const;
};

// Which of the child's output streams go to pipes this process reads (the others are
// inherited).
struct Capture {
  bool out = false;
  bool err = false;
};

enum class Stream { Out = 0, Err = 1 };

// What a captured child left when it ended.
struct Finished {
  ExitStatus status;
  std::string out;  // the rest of stdout (what read_line had not taken)
  std::string err;
  bool killed = false;  // it overstayed the timeout and was killed
};

class ChildProcess {
 public:
  // Starts `argv[0]` (a path, or a name looked up in PATH) with the given arguments and this
  // process's environment, plus `env` ("NAME=value", replacing a variable of that name);
  // throws std::runtime_error naming the program when it cannot be started.
  explicit ChildProcess(std::vector<std::string> argv, std::vector<std::string> env = {},
                        Capture capture = {});
  ~ChildProcess();  // terminates and reaps a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&&) = delete;

  pid_t pid() const { return pid_; }
  const std::string& program() const { return argv_.front(); }

  // Non-blocking: the exit status once the child has ended, nullopt while it runs.
  std::optional<ExitStatus> poll();
  // Whether the child is stopped by a signal (SIGSTOP, SIGTSTP: state T in /proc), so not
  // running although it has not ended.
  bool stopped() const;
  // Waits up to `timeout` for the child to end by itself.
  std::optional<ExitStatus> wait_for(std::chrono::milliseconds timeout);
  // Sends `sig` to a child that has not been reaped.
  void signal(int sig);
  // SIGTERM without waiting: an owner ending several children asks them all first, then
  // reaps each (terminate), so their grace periods overlap.
  void request_stop();
  // SIGTERM, then SIGKILL if it has not ended after `grace`; always reaps.
  ExitStatus terminate(std::chrono::milliseconds grace = std::chrono::milliseconds(500));

  // The next line (without '\n') of a captured stream, or nullopt at its end or after
  // `timeout`.
  std::optional<std::string> read_line(Stream stream, std::chrono::milliseconds timeout);
  // Collects the rest of the captured streams until the child closes them, then reaps it;
  // after `timeout` it is killed (and the result says so).
  Finished finish(std::chrono::milliseconds timeout);

 private:
  // Reads what the captured streams have within `timeout`; false when both are closed.
  bool pump(std::chrono::milliseconds timeout);

  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  std::optional<ExitStatus> status_;
  Fd pipes_[2];
  std::string buffers_[2];
};

// Runs to completion with both streams captured (bounded by `timeout`).
Finished run(std::vector<std::string> argv, std::chrono::milliseconds timeout);
// Runs `command` with /bin/sh, its stderr joined to its stdout in `out` (as a terminal shows
// them), bounded by `timeout`.
Finished run_shell(const std::string& command, std::chrono::milliseconds timeout);

}  // namespace l2
