// The process end of one pipeserver of a run: a child process this run started, or an MPI rank
// mpirun started on some machine. The pipeserver set asks it what it needs (has it ended, is it
// stopped, how to name it, end it) without knowing which it is.
//
// Example:
//   std::unique_ptr<PipeserverProcess> p = child_pipeserver_process({"pipeserver", "--live", ...},
//   {}); if (const auto exit = p->poll(); exit && !exit->ok())
//     fmt::print("pipeserver 0 ({}) {}\n", p->place(), exit->describe());  // "(pid 4242) ..."
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/child_process.hpp"

namespace l2 {

class PipeserverProcess {
 public:
  virtual ~PipeserverProcess() = default;
  // How messages name it: "pid 4242", or "rank 3 on node-a, pid 4242".
  virtual std::string place() const = 0;
  // Its exit status once it has ended; nullopt while it runs. An MPI rank's is only ever
  // ExitStatus::gone, once its liveness connection closed.
  virtual std::optional<ExitStatus> poll() = 0;
  // Stopped by a signal (SIGSTOP), as far as this process can tell.
  virtual bool stopped() const = 0;
  // Whether the run waits for it to end by itself after the last frame.
  virtual bool awaited() const = 0;
  // Asks it to end (SIGTERM) without waiting.
  virtual void request_stop() = 0;
  // Ends it (SIGTERM, then SIGKILL after `grace`) and reaps it; nullopt when not ours to end.
  virtual std::optional<ExitStatus> terminate(std::chrono::milliseconds grace) = 0;
};

// A pipeserver process started here with `argv` and `env` ("NAME=value" added).
std::unique_ptr<PipeserverProcess> child_pipeserver_process(const std::vector<std::string>& argv,
                                                            const std::vector<std::string>& env);
// A pipeserver another process started (an MPI rank), named by `place`; `gone` says whether
// its process was seen to end, `how` (if given) how it was found gone (ExitStatus::gone_how),
// `code` (if given) the exit code it said it ended with: then its end is that exit status, as a
// child's is.
std::unique_ptr<PipeserverProcess> remote_pipeserver_process(
    std::string place, std::function<bool()> gone, std::function<std::string()> how = {},
    std::function<std::optional<int>()> code = {});

}  // namespace l2
