// The compositors of the one-machine viz path (compositors.hpp): the compositing server process
// (VizserverProcess) composes every display from the pipeservers' tiles and sends SWAPPED
// itself; its display stream brings each frame here.
//
// Owns: the server process and its stream. It may not decide what the run does on a fault: it
// words what happened (its words name a pipeserver where the server said so).
#pragma once

#include <memory>

#include "l2wall/compositors.hpp"
#include "vizserver_process.hpp"

namespace l2 {

class ServerCompositor final : public Compositors {
 public:
  explicit ServerCompositor(const VizLaunch& launch)
      : server_(std::make_unique<VizserverProcess>(launch)) {}

  void add_pipeserver_args(PipeserverLaunch& launch) const override {
    launch.viz_address = server_->address();
    launch.env.push_back(server_->token_variable());
  }
  bool composed(int frame, std::chrono::milliseconds wait) override {
    return server_->frame(frame, wait) != nullptr;
  }
  // Asking the server's stream again for the frame last returned gives it again.
  DisplayPictures pictures(int frame) override {
    return pictures_of(server_->frame(frame, std::chrono::milliseconds(0)));
  }
  std::optional<DisplayPictures> shown() const override;
  int frame_shown() const override;

  bool down() override { return server_->down(); }
  void settle(std::chrono::milliseconds grace) override { server_->settle(grace); }
  Status failure_as_cause(int shown, const std::string& showing) override;
  Status failure(int shown, const std::string& showing) override {
    return Failure{server_->describe_down(shown, showing)};
  }
  Status hang_behind(const LivePipeserver& h, int shown, const std::string& showing) override;
  std::string process_name() const override { return server_->name(); }

  void lose(int pipeserver) override { server_->lose_pipeserver(pipeserver); }
  void finish() override { server_->finish(std::chrono::milliseconds(5000)); }
  void shut_down() override { server_->shut_down(); }

 private:
  static DisplayPictures pictures_of(const viz::FramePtr& f) {
    return [f](int id) -> const RgbImage& { return f->displays.at(static_cast<std::size_t>(id)); };
  }

  std::unique_ptr<VizserverProcess> server_;
};

}  // namespace l2
