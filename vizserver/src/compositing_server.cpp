#include "vizserver/compositing_server.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "server_loop.hpp"

namespace l2::viz {

CompositingServer::CompositingServer(ServerOptions options)
    : options_(std::move(options)), shared_(std::make_shared<ServerShared>()) {
  if (options_.pipeservers < 1)
    throw std::invalid_argument("vizserver: need at least 1 pipeserver");
  if (options_.display_sizes.empty()) throw std::invalid_argument("vizserver: no displays");
  listener_ = listen_tcp(options_.host, options_.port);
  port_ = local_port(listener_.get());
}

CompositingServer::~CompositingServer() {
  stop();
}

void CompositingServer::on_swap(std::function<void(const FramePtr&)> callback) {
  if (loop_) throw std::logic_error("CompositingServer::on_swap after start()");
  on_swap_ = std::move(callback);
}

void CompositingServer::start() {
  if (loop_ || !listener_) throw std::logic_error("CompositingServer::start called twice");
  loop_ = std::make_unique<ServerLoop>(options_, std::move(listener_), port_, shared_, on_swap_);
}

void CompositingServer::lose_pipeserver(int pipeserver) {
  if (loop_) loop_->lose(pipeserver);
}

void CompositingServer::stop() {
  loop_.reset();  // the loop's destructor wakes and joins its thread
  listener_.reset();
}

FramePtr CompositingServer::wait_frame(std::uint32_t frame, std::chrono::milliseconds timeout) {
  std::unique_lock lock(shared_->mutex);
  auto find = [&]() -> FramePtr {
    for (const FramePtr& f : shared_->recent) {
      if (f->frame == frame) return f;
    }
    return nullptr;
  };
  shared_->changed.wait_for(lock, timeout, [&] {
    return find() || shared_->ended || shared_->failure ||
           (shared_->last_swapped && *shared_->last_swapped >= frame);
  });
  if (FramePtr f = find()) return f;
  if (shared_->failure) throw NetError(*shared_->failure);
  if (shared_->last_swapped && *shared_->last_swapped >= frame) {
    throw NetError(
        fmt::format("frame {} is not available: no pipeserver sent it, or it was "
                    "swapped more than {} frames ago (last swapped: {})",
                    frame, options_.recent_frames, *shared_->last_swapped));
  }
  if (shared_->ended) {
    throw NetError(shared_->all_left
                       ? fmt::format("every pipeserver finished and disconnected; frame {} "
                                     "never arrived",
                                     frame)
                       : fmt::format("the server stopped before frame {} was swapped", frame));
  }
  throw NetError(fmt::format(
      "frame {} not swapped within {} ms (last swapped: {})", frame, timeout.count(),
      shared_->last_swapped ? fmt::to_string(*shared_->last_swapped) : std::string("none")));
}

bool CompositingServer::wait_finished(std::chrono::milliseconds timeout) {
  std::unique_lock lock(shared_->mutex);
  return shared_->changed.wait_for(lock, timeout, [&] { return shared_->ended; });
}

Status CompositingServer::failure() const {
  std::lock_guard lock(shared_->mutex);
  if (shared_->failure) return Failure{*shared_->failure};
  return {};
}

std::vector<std::string> CompositingServer::errors() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->errors;
}

std::uint64_t CompositingServer::error_count() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->error_count;
}

StripErrorCounts CompositingServer::counts() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->counts;
}

std::optional<std::uint32_t> CompositingServer::last_swapped() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->last_swapped;
}

}  // namespace l2::viz
