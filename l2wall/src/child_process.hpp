// A child process the live run owns: started with posix_spawn, watched without blocking, and
// always reaped — a run that ends for any reason leaves no orphan behind.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace l2 {

struct ExitStatus {
  int code = 0;    // exit code when the process exited
  int signal = 0;  // terminating signal, 0 if it exited
  bool ok() const { return signal == 0 && code == 0; }
  std::string describe() const;  // "exited with code 3" / "killed by signal 9 (Killed)"
};

class ChildProcess {
 public:
  // Starts `argv[0]` (a path) with the given arguments and this process's environment, plus
  // `env` ("NAME=value", replacing a variable of that name); throws std::runtime_error naming
  // the program when it cannot be started.
  explicit ChildProcess(std::vector<std::string> argv, std::vector<std::string> env = {});
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
  // SIGTERM without waiting: a run ending several children asks them all first, then reaps
  // each (terminate), so their grace periods overlap.
  void request_stop();
  // SIGTERM, then SIGKILL if it has not ended after `grace`; always reaps.
  ExitStatus terminate(std::chrono::milliseconds grace = std::chrono::milliseconds(500));

 private:
  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  std::optional<ExitStatus> status_;
};

}  // namespace l2
