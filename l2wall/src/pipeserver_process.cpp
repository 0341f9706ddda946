#include "l2wall/pipeserver_process.hpp"

#include <functional>
#include <utility>

namespace l2 {
namespace {

class ChildPipeserver final : public PipeserverProcess {
 public:
  ChildPipeserver(const std::vector<std::string>& argv, const std::vector<std::string>& env)
      : process_(argv, env) {}
  std::string place() const override { return "pid " + std::to_string(process_.pid()); }
  std::optional<ExitStatus> poll() override { return process_.poll(); }
  bool stopped() const override { return process_.stopped(); }
  bool awaited() const override { return true; }
  void request_stop() override { process_.request_stop(); }
  std::optional<ExitStatus> terminate(std::chrono::milliseconds grace) override {
    return process_.terminate(grace);
  }

 private:
  ChildProcess process_;
};

// Watched from elsewhere: the coordinator learns of a rank's end from its liveness connection
// (mpi/), and mpirun reaps it.
class RemotePipeserver final : public PipeserverProcess {
 public:
  RemotePipeserver(std::string place, std::function<bool()> gone, std::function<std::string()> how,
                   std::function<std::optional<int>()> code)
      : place_(std::move(place)),
        gone_(std::move(gone)),
        how_(std::move(how)),
        code_(std::move(code)) {}
  std::string place() const override { return place_; }
  std::optional<ExitStatus> poll() override {
    if (!gone_()) return std::nullopt;
    ExitStatus s;
    if (const std::optional<int> code = code_ ? code_() : std::nullopt) {
      s.code = *code;
      return s;
    }
    s.gone = true;
    if (how_) s.gone_how = how_();
    return s;
  }
  bool stopped() const override { return false; }
  bool awaited() const override { return false; }
  void request_stop() override {}
  std::optional<ExitStatus> terminate(std::chrono::milliseconds) override { return std::nullopt; }

 private:
  std::string place_;
  std::function<bool()> gone_;
  std::function<std::string()> how_;
  std::function<std::optional<int>()> code_;
};

}  // namespace

std::unique_ptr<PipeserverProcess> child_pipeserver_process(const std::vector<std::string>& argv,
                                                            const std::vector<std::string>& env) {
  return std::make_unique<ChildPipeserver>(argv, env);
}

std::unique_ptr<PipeserverProcess> remote_pipeserver_process(
    std::string place, std::function<bool()> gone, std::function<std::string()> how,
    std::function<std::optional<int>()> code) {
  return std::make_unique<RemotePipeserver>(std::move(place), std::move(gone), std::move(how),
                                            std::move(code));
}

}  // namespace l2
