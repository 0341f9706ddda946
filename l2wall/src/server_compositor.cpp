#include "server_compositor.hpp"

#include <fmt/format.h>

#include "pipeserver/live_exit.hpp"

namespace l2 {

std::optional<DisplayPictures> ServerCompositor::shown() const {
  if (!server_->last()) return std::nullopt;
  return pictures_of(server_->last());
}

int ServerCompositor::frame_shown() const {
  return server_->last() ? static_cast<int>(server_->last()->frame) : -1;
}

Status ServerCompositor::failure_as_cause(int shown, const std::string& showing) {
  if (server_->down() && !server_->said_why())
    return Failure{server_->describe_down(shown, showing)};
  return {};
}

// A pipeserver waits for SWAPPED only ready-timeout x retries, often less than --stall-timeout: one
// that gave up on a server still running means the server hangs.
Status ServerCompositor::hang_behind(const LivePipeserver& h, int shown,
                                     const std::string& showing) {
  if (server_->down() || !h.exit || h.exit->code != kExitLostCompositingServer) return {};
  return Failure{
      fmt::format("the {} stopped answering: pipeserver {} gave up waiting for it at frame {}; {}",
                  server_->name(), h.pipeserver, shown, showing)};
}

}  // namespace l2
