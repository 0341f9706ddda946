#include "l2wall/pipeserver_set.hpp"

#include <fmt/format.h>

#include <fcntl.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "l2wall/run_fault.hpp"
#include "l2wall/run_time.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

int frames_reported(const std::string& pipeserver_log) {
  std::ifstream in(pipeserver_log);
  int frames = 0;
  for (std::string line; std::getline(in, line);) frames += line.rfind("frame ", 0) == 0;
  return frames;
}

}  // namespace

std::vector<std::string> pipeserver_argv(const PipeserverLaunch& l, const LivePipeserver& h) {
  std::vector<std::string> argv{l.program,         "--live",
                                "--pipeserver",    std::to_string(h.pipeserver),
                                "--frames",        std::to_string(l.frames),
                                "--scene",         l.scene,
                                "--report",        h.report_path,
                                "--ready-timeout", std::to_string(l.ready_timeout_ms)};
  argv.insert(argv.end(), l.scene_args.begin(), l.scene_args.end());
  if (l.dvi) {
    for (const std::string& a :
         {std::string("--link"), h.link_name, std::string("--backchannel"), h.pty->slave_path()})
      argv.push_back(a);
  }
  if (!l.viz_address.empty()) {
    argv.push_back("--viz");
    argv.push_back(l.viz_address);
  }
  if (!l.wall.empty()) {
    argv.push_back("--wall");
    argv.push_back(l.wall);
  }
  if (!l.link_codec.empty()) {
    argv.push_back("--link-codec");
    argv.push_back(l.link_codec);
  }
  if (!l.renderer.empty()) {
    argv.push_back("--renderer");
    argv.push_back(l.renderer);
  }
  argv.insert(argv.end(), l.extra_args.begin(), l.extra_args.end());
  return argv;
}

namespace {

// The frame's stamp is read in its stamp strip (or, where the framebuffer has no room for one,
// its first tile's first pixel); the display named is where its first tile goes, which the board
// columns' bookkeeping asks for the frame shown.
StampSpot stamp_spot(const PipeserverPlan& plan) {
  if (plan.tiles.empty()) return {};
  const PackedTile& t = plan.tiles.front();
  StampSpot s{t.fb_x, t.fb_y, t.tile.display, t.tile.on_display.x, t.tile.on_display.y};
  if (plan.has_stamp_strip()) {
    s.fb_x = plan.stamp_x;
    s.fb_y = plan.rows[static_cast<std::size_t>(plan.stamp_row)].y;
  }
  return s;
}

// The pipeserver's end gets a descriptor number on its command line; ours must not leak into
// the other pipeservers, or a dead pipeserver's channel would never read as closed.
// Returns the pipeserver's end, to be closed here once the process holds its copy.
// `option`: how the pipeserver is told the number (--control-fd, --windows-fd); `ours` gets our
// end.
SocketControlChannel open_channel(std::unique_ptr<ControlChannel>& ours, const char* option,
                                  std::vector<std::string>& argv) {
  auto [mine, theirs] = control_socket_pair();
  if (::fcntl(mine.fd(), F_SETFD, FD_CLOEXEC) != 0)
    throw std::runtime_error(fmt::format("{}: fcntl(FD_CLOEXEC) failed", option));
  argv.push_back(option);
  argv.push_back(std::to_string(theirs.fd()));
  ours = std::make_unique<SocketControlChannel>(std::move(mine));
  return std::move(theirs);
}

}  // namespace

// One entry a frame up to `from`, the frames between keeping the previous layout's spot: a
// long run re-tiled at every frame then costs one entry a frame, not a fill to its end.
void PipeserverSet::place_stamps(const TileLayout& layout, int from) {
  const auto at = static_cast<std::size_t>(std::max(from, 0));
  for (std::size_t i = 0; i < pipeservers_.size(); ++i) {
    LivePipeserver& h = pipeservers_[i];
    const StampSpot before = h.stamps.empty() ? StampSpot{} : h.stamps.back();
    h.stamps.resize(at, before);
    h.stamps.push_back(stamp_spot(layout.pipeservers[i]));
  }
}

void PipeserverSet::start(const PipeserverLaunch& launch, const TileLayout& layout) {
  dvi_ = launch.dvi;
  frames_ = launch.frames;
  for (std::size_t i = 0; i < layout.pipeservers.size(); ++i) {
    // Joins the set once its process runs, so every pipeserver in it has one (the pty stays put: it
    // is owned through a pointer).
    LivePipeserver h;
    h.pipeserver = static_cast<int>(i);
    h.link_name = dvi_link_name(fmt::format("in{}", i));
    h.report_path = (launch.out / fmt::format("pipeserver-{}.log", i)).string();
    std::filesystem::remove(h.report_path);
    h.pty = std::make_unique<PtyPair>(PtyPair::open());
    h.channel = std::make_unique<BackChannel>(h.pty->master());
    std::vector<std::string> argv = pipeserver_argv(launch, h);
    std::vector<SocketControlChannel> theirs;
    if (launch.control) theirs.push_back(open_channel(h.control, "--control-fd", argv));
    if (launch.windows) theirs.push_back(open_channel(h.windows, "--windows-fd", argv));
    h.process = child_pipeserver_process(argv, launch.env);
    pipeservers_.push_back(std::move(h));
  }
  place_stamps(layout, 0);
}

void PipeserverSet::attach(const PipeserverLaunch& launch, const TileLayout& layout,
                           const std::function<RemoteEnd(int pipeserver)>& connect) {
  dvi_ = launch.dvi;
  frames_ = launch.frames;
  for (std::size_t i = 0; i < layout.pipeservers.size(); ++i) {
    LivePipeserver& h = pipeservers_.emplace_back();
    h.pipeserver = static_cast<int>(i);
    // Its own (it may have started writing it already).
    h.report_path = (launch.out / fmt::format("pipeserver-{}.log", i)).string();
    RemoteEnd end = connect(h.pipeserver);
    h.process = std::move(end.process);
    h.channel = std::move(end.channel);
    h.control = std::move(end.control);
    h.windows = std::move(end.windows);
  }
  place_stamps(layout, 0);
}

LivePipeserver* PipeserverSet::poll_ended() {
  for (LivePipeserver& h : serving()) {
    if (!h.exit) h.exit = h.process->poll();
  }
  for (LivePipeserver& h : serving()) {
    if (h.exit && (!h.exit->ok() || delivered(h) < frames_)) return &h;
  }
  return nullptr;
}

LivePipeserver* PipeserverSet::killed_by_signal() {
  poll_ended();
  for (LivePipeserver& h : serving()) {
    // Only asked while the run has ended no pipeserver itself, so no signal here is ours.
    if (h.exit && h.exit->signal != 0) return &h;
  }
  return nullptr;
}

std::string PipeserverSet::ended_how(const LivePipeserver& h) const {
  return fmt::format("pipeserver {} ({}) {} while rendering frame {}", h.pipeserver,
                     h.process->place(), h.exit ? h.exit->describe() : std::string("ended"),
                     delivered(h));
}

std::string PipeserverSet::describe_end(const LivePipeserver& h,
                                        const std::string& on_displays) const {
  return fmt::format("{}; {}", ended_how(h), on_displays);
}

void PipeserverSet::open_links(milliseconds timeout, const std::function<void()>& check) {
  const auto deadline = RunClock::now() + timeout;
  for (;;) {
    check();
    bool all = true;
    for (LivePipeserver& h : pipeservers_) {
      if (h.lost) continue;  // survived before its first frame: its link never opens
      if (!h.reader) {
        try {
          h.reader = std::make_unique<DviLinkReader>(DviLinkReader::open(h.link_name));
        } catch (const DviLinkError&) {
          // not created yet
        }
      }
      if (!h.reader || !h.reader->latest()) all = false;
    }
    // The emulator starts once every link carries a signal: an input without one feeds no
    // group, so a group would otherwise swap with only the pipeservers that happened to be first.
    if (all) return;
    if (RunClock::now() > deadline) {
      std::string missing;
      for (const LivePipeserver& h : pipeservers_)
        if (!h.lost && (!h.reader || h.sequence == 0)) missing += fmt::format(" {}", h.pipeserver);
      throw RunFault(fmt::format("no first frame within {} ms from pipeserver(s){}",
                                 timeout.count(), missing));
    }
    std::this_thread::sleep_for(milliseconds(5));
  }
}

bool PipeserverSet::take_in(std::vector<InputFrame>& inputs) {
  bool fresh = false;
  for (std::size_t i = 0; i < pipeservers_.size(); ++i) {
    LivePipeserver& h = pipeservers_[i];
    if (h.lost) {
      // No signal: it feeds no group and holds none up. Losing the signal is news too: a
      // group it held up can complete now, even if no other link changes.
      if (inputs[i].present()) fresh = true;
      inputs[i] = {};
      continue;
    }
    const auto f = h.reader->latest();
    if (!f) continue;
    inputs[i] = {f->pixels, static_cast<std::ptrdiff_t>(f->stride), f->width, f->height, 3};
    if (f->sequence != h.sequence) fresh = true;
    h.sequence = f->sequence;
  }
  return fresh;
}

void PipeserverSet::serve_channels() {
  if (!dvi_) return;
  for (LivePipeserver& h : serving()) {
    const auto& c = h.channel->counts();
    const auto asked = c.sync_answered + c.sync_unanswered;
    h.channel->serve(milliseconds(0));
    if (h.held_ready && c.sync_answered + c.sync_unanswered > asked) {
      h.channel->send_ready(static_cast<std::uint64_t>(*h.held_ready));
      h.held_ready.reset();
    }
  }
}

std::uint64_t PipeserverSet::inject_noise() {
  static const char kNoise[] = "RE\x01\xffz9 READY 12 ZZ\r\nSYNC? 0\x7f\x80 R";
  std::uint64_t bytes = 0;
  for (LivePipeserver& h : pipeservers_) {
    if (!h.pty) continue;  // no serial line to put noise on
    h.pty->master().write_some(std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(kNoise), sizeof kNoise - 1));
    bytes += sizeof kNoise - 1;
  }
  return bytes;
}

int PipeserverSet::delivered(const LivePipeserver& h) const {
  return dvi_ ? static_cast<int>(h.sequence) : frames_reported(h.report_path);
}

std::string PipeserverSet::late_pipeservers(int shown) const {
  std::string culprits;
  for (const LivePipeserver& h : serving()) {
    if (delivered(h) < shown + 1)
      culprits += fmt::format("{}pipeserver {} ({})", culprits.empty() ? "" : ", ", h.pipeserver,
                              h.process->place());
  }
  return culprits;
}

const LivePipeserver* PipeserverSet::hung_pipeserver(int shown) {
  poll_ended();
  const LivePipeserver* late = nullptr;
  for (const LivePipeserver& h : serving()) {
    if (h.exit || delivered(h) >= shown + 1) continue;
    if (h.process->stopped()) return &h;
    if (!late) late = &h;
  }
  return late;
}

std::string PipeserverSet::stopped_note(const LivePipeserver& h) {
  return h.process->stopped() ? " (stopped by a signal)" : "";
}

void PipeserverSet::finish(milliseconds timeout) {
  const auto deadline = RunClock::now() + timeout;
  for (;;) {
    serve_channels();
    bool all = true;
    for (LivePipeserver& h : serving()) {
      if (!h.process->awaited()) continue;  // mpirun ends it
      if (!h.exit) h.exit = h.process->poll();
      if (!h.exit) {
        all = false;
      } else if (!h.exit->ok()) {
        throw RunFault(
            fmt::format("pipeserver {} {} after the last frame", h.pipeserver, h.exit->describe()));
      }
    }
    if (all) return;
    if (RunClock::now() > deadline) throw RunFault("pipeservers did not end after the last frame");
    std::this_thread::sleep_for(milliseconds(2));
  }
}

void PipeserverSet::request_stop() {
  for (LivePipeserver& h : pipeservers_) {
    if (!h.exit) h.process->request_stop();
  }
}

void PipeserverSet::shut_down() {
  for (LivePipeserver& h : pipeservers_) {
    if (!h.exit) h.exit = h.process->terminate(milliseconds(500));
    h.reader.reset();
    if (h.link_name.empty()) continue;  // none of ours
    try {
      remove_stale(h.link_name);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: %s\n", e.what());
    }
  }
}

}  // namespace l2
