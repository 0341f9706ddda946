#include "vizserver_process.hpp"

#include <fmt/format.h>

#include <thread>

#include "base/socket.hpp"
#include "l2wall/run_fault.hpp"
#include "l2wall/run_time.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

// Swapped frames the stream reader holds for us; the server waits (and so do the pipeservers)
// when we fall further behind, e.g. while writing saved pictures.
constexpr std::size_t kHeldFrames = 4;

std::vector<std::string> vizserver_argv(const VizLaunch& l, std::uint16_t stream_port) {
  std::string sizes;
  for (const auto& [w, h] : l.display_sizes)
    sizes += fmt::format("{}{}x{}", sizes.empty() ? "" : ",", w, h);
  return {l.program, "--displays", sizes, "--pipeservers", std::to_string(l.pipeservers),
          "--viz-host", l.host, "--viz-port", std::to_string(l.port), "--frames",
          std::to_string(l.frames), "--display-stream", fmt::format("127.0.0.1:{}", stream_port),
          "--log", l.log.string(), "--accept-timeout", std::to_string(l.start_timeout.count()),
          // A pipeserver that hangs is ours to name (the run's stall timeout), not the server's.
          "--stall-timeout", "0"};
}

std::vector<std::string> vizserver_args(const VizLaunch& l, std::uint16_t stream_port) {
  std::vector<std::string> argv = vizserver_argv(l, stream_port);
  if (l.survive_losses) argv.push_back("--survive-loss");
  return argv;
}

}  // namespace

VizserverProcess::VizserverProcess(const VizLaunch& launch)
    : host_(launch.host), token_(viz::new_run_token()) {
  // Our end of the display stream, on loopback: the server is our child on this machine.
  const Fd listener = listen_tcp("127.0.0.1", 0);
  process_.emplace(vizserver_args(launch, local_port(listener.get())),
                   std::vector<std::string>{token_variable()});
  accept_stream(listener, launch);
}

std::string VizserverProcess::token_variable() const {
  return fmt::format("{}={}", viz::kTokenVariable, viz::token_text(token_));
}

std::string VizserverProcess::name() const {
  return fmt::format("compositing server (vizserver pid {})", pid());
}

VizserverProcess::~VizserverProcess() {
  shut_down();
}

void VizserverProcess::accept_stream(const Fd& listener, const VizLaunch& launch) {
  const std::string who = name();
  const auto deadline = RunClock::now() + launch.start_timeout;
  Fd stream;
  while (!stream) {
    if ((exit_ = process_->poll())) {
      throw RunFault(fmt::format("{} {} before it listened", who, exit_->describe()));
    }
    if (RunClock::now() > deadline) {
      throw RunFault(fmt::format("{} did not connect its display stream within {} ms", who,
                                 launch.start_timeout.count()));
    }
    stream = viz::accept_within(listener, milliseconds(20));
  }
  viz::Listening listening;
  try {
    listening = viz::read_listening(stream.get(), deadline, who);
  } catch (const NetError& e) {
    throw RunFault(e.what());  // e.g. "...: cannot listen on 127.0.0.1:5000: Address in use"
  }
  if (listening.display_count != launch.display_sizes.size() ||
      listening.pipeserver_count != static_cast<std::uint32_t>(launch.pipeservers)) {
    throw RunFault(fmt::format("{} composes {} displays for {} pipeservers, the wall has {} and {}",
                               who, listening.display_count, listening.pipeserver_count,
                               launch.display_sizes.size(), launch.pipeservers));
  }
  port_ = static_cast<std::uint16_t>(listening.port);
  watcher_ = std::make_unique<viz::DisplayWatcher>(std::move(stream), who, listening.display_count,
                                                   kHeldFrames);
}

std::string VizserverProcess::address() const {
  const std::string host = host_ == "0.0.0.0" ? "127.0.0.1" : host_ == "::" ? "::1" : host_;
  return fmt::format("{}:{}", host, port_);
}

viz::FramePtr VizserverProcess::frame(int frame, milliseconds timeout) {
  if (last_ && last_->frame == static_cast<std::uint32_t>(frame)) return last_;
  if (stream_error_ || !watcher_) return nullptr;
  try {
    viz::FramePtr f = watcher_->take(static_cast<std::uint32_t>(frame), timeout);
    if (f) last_ = f;
    return f;
  } catch (const NetError& e) {
    stream_error_ = e.what();
    return nullptr;
  }
}

void VizserverProcess::lose_pipeserver(int pipeserver) {
  if (!watcher_ || stream_error_) return;
  try {
    watcher_->send_lost(static_cast<std::uint32_t>(pipeserver));
  } catch (const NetError& e) {
    stream_error_ = e.what();
  }
}

bool VizserverProcess::down() {
  if (!exit_ && process_) exit_ = process_->poll();
  // A server that exits 0 has sent every frame: they are still ours to take.
  return stream_error_.has_value() || (exit_ && !exit_->ok());
}

void VizserverProcess::settle(milliseconds grace) {
  // Its stream ended: the process is gone or going, give the kernel a moment to say how.
  const bool going = stream_error_ || (watcher_ && !watcher_->ended().ok());
  const auto deadline = RunClock::now() + (going ? grace : grace / 3);
  while (!exit_ && process_ && RunClock::now() < deadline) {
    exit_ = process_->poll();
    if (!exit_) std::this_thread::sleep_for(milliseconds(5));
  }
}

bool VizserverProcess::said_why() const {
  return exit_ && exit_->signal == 0 && exit_->code != 0 && watcher_ &&
         watcher_->ended_with_error_message();
}

std::string VizserverProcess::describe_down(int shown, const std::string& on_displays) const {
  const std::string who = name();
  if (said_why()) {
    return fmt::format("{} failed at frame {}: {}; {}", who, shown, watcher_->ended().reason(),
                       on_displays);
  }
  if (exit_ && !exit_->ok()) {
    return fmt::format("{} {} at frame {}; {}", who, exit_->describe(), shown, on_displays);
  }
  return fmt::format("{} at frame {}: {}; {}", who, shown,
                     stream_error_.value_or("display stream ended"), on_displays);
}

void VizserverProcess::finish(milliseconds timeout) {
  const std::string who = name();
  if (!exit_) exit_ = process_->wait_for(timeout);
  if (!exit_) throw RunFault(who + " did not end after the last frame");
  if (!exit_->ok())
    throw RunFault(fmt::format("{} {} after the last frame", who, exit_->describe()));
}

void VizserverProcess::shut_down() {
  if (process_ && !exit_) exit_ = process_->terminate(milliseconds(500));
  watcher_.reset();  // after the process: its stream has ended, the reader returns at once
}

}  // namespace l2
