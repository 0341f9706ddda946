#include "host_set.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <thread>

#include "run_fault.hpp"
#include "run_time.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

int frames_reported(const std::string& host_log) {
  std::ifstream in(host_log);
  int frames = 0;
  for (std::string line; std::getline(in, line);) frames += line.rfind("frame ", 0) == 0;
  return frames;
}

}  // namespace

std::vector<std::string> host_argv(const HostLaunch& l, const Host& h) {
  std::vector<std::string> argv{l.pipeserver,      "--live",
                                "--server",        std::to_string(h.server),
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
  argv.insert(argv.end(), l.extra_args.begin(), l.extra_args.end());
  return argv;
}

namespace {

// Where host i's frame stamp is: its first tile's framebuffer pixel and the display pixel it
// lands on.
void place_stamp(Host& h, const ServerPlan& plan) {
  if (plan.tiles.empty()) return;
  const PackedTile& t = plan.tiles.front();
  h.fb_x = t.fb_x;
  h.fb_y = t.fb_y;
  h.display = t.tile.display;
  h.dx = t.tile.on_display.x;
  h.dy = t.tile.on_display.y;
}

}  // namespace

void HostSet::start(const HostLaunch& launch, const TileLayout& layout) {
  dvi_ = launch.dvi;
  frames_ = launch.frames;
  for (std::size_t i = 0; i < layout.servers.size(); ++i) {
    Host& h = hosts_.emplace_back();
    h.server = static_cast<int>(i);
    h.link_name = dvi_link_name(fmt::format("in{}", i));
    h.report_path = (launch.out / fmt::format("host-{}.log", i)).string();
    std::filesystem::remove(h.report_path);
    h.pty = std::make_unique<PtyPair>(PtyPair::open());
    h.channel = std::make_unique<BackChannel>(h.pty->master());
    place_stamp(h, layout.servers[i]);
    h.process.emplace(host_argv(launch, h), launch.env);
  }
}

void HostSet::attach(const HostLaunch& launch, const TileLayout& layout,
                     const std::function<std::unique_ptr<ReadyChannel>(int server)>& channel) {
  dvi_ = launch.dvi;
  frames_ = launch.frames;
  for (std::size_t i = 0; i < layout.servers.size(); ++i) {
    Host& h = hosts_.emplace_back();
    h.server = static_cast<int>(i);
    // Its own (it may have started writing it already).
    h.report_path = (launch.out / fmt::format("host-{}.log", i)).string();
    h.channel = channel(h.server);
    place_stamp(h, layout.servers[i]);
  }
}

Host* HostSet::poll_ended() {
  for (Host& h : hosts_) {
    if (!h.exit && h.process) h.exit = h.process->poll();
  }
  for (Host& h : hosts_) {
    if (h.exit && (!h.exit->ok() || delivered(h) < frames_)) return &h;
  }
  return nullptr;
}

Host* HostSet::killed_by_signal() {
  poll_ended();
  for (Host& h : hosts_) {
    // Only asked while the run has ended no host itself, so no signal here is ours.
    if (h.exit && h.exit->signal != 0) return &h;
  }
  return nullptr;
}

std::string HostSet::describe_end(const Host& h, const std::string& on_displays) const {
  return fmt::format("pipeserver {} (pid {}) {} while rendering frame {}; {}", h.server,
                     h.process ? h.process->pid() : -1,
                     h.exit ? h.exit->describe() : std::string("ended"), delivered(h), on_displays);
}

void HostSet::open_links(milliseconds timeout, const std::function<void()>& check) {
  const auto deadline = RunClock::now() + timeout;
  for (;;) {
    check();
    bool all = true;
    for (Host& h : hosts_) {
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
    // group, so a group would otherwise swap with only the hosts that happened to be first.
    if (all) return;
    if (RunClock::now() > deadline) {
      std::string missing;
      for (const Host& h : hosts_)
        if (!h.reader || h.sequence == 0) missing += fmt::format(" {}", h.server);
      throw RunFault(fmt::format("no first frame within {} ms from pipeserver(s){}",
                                 timeout.count(), missing));
    }
    std::this_thread::sleep_for(milliseconds(5));
  }
}

bool HostSet::take_in(std::vector<InputFrame>& inputs) {
  bool fresh = false;
  for (std::size_t i = 0; i < hosts_.size(); ++i) {
    Host& h = hosts_[i];
    const auto f = h.reader->latest();
    if (!f) continue;
    inputs[i] = {f->pixels, static_cast<std::ptrdiff_t>(f->stride), f->width, f->height, 3};
    if (f->sequence != h.sequence) fresh = true;
    h.sequence = f->sequence;
  }
  return fresh;
}

void HostSet::serve_channels() {
  if (!dvi_) return;
  for (Host& h : hosts_) {
    const auto& c = h.channel->counts();
    const auto asked = c.sync_answered + c.sync_unanswered;
    h.channel->serve(milliseconds(0));
    if (h.held_ready && c.sync_answered + c.sync_unanswered > asked) {
      h.channel->send_ready(static_cast<std::uint64_t>(*h.held_ready));
      h.held_ready.reset();
    }
  }
}

std::uint64_t HostSet::inject_noise() {
  static const char kNoise[] = "RE\x01\xffz9 READY 12 ZZ\r\nSYNC? 0\x7f\x80 R";
  std::uint64_t bytes = 0;
  for (Host& h : hosts_) {
    if (!h.pty) continue;  // no serial line to put noise on
    h.pty->master().write_some(std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(kNoise), sizeof kNoise - 1));
    bytes += sizeof kNoise - 1;
  }
  return bytes;
}

int HostSet::delivered(const Host& h) const {
  return dvi_ ? static_cast<int>(h.sequence) : frames_reported(h.report_path);
}

std::string HostSet::late_hosts(int shown) const {
  std::string culprits;
  for (const Host& h : hosts_) {
    if (delivered(h) < shown + 1)
      culprits += fmt::format("{}pipeserver {} ({})", culprits.empty() ? "" : ", ", h.server,
                              h.process ? fmt::format("pid {}", h.process->pid()) : h.place);
  }
  return culprits;
}

const Host* HostSet::hung_host(int shown) {
  poll_ended();
  const Host* late = nullptr;
  for (const Host& h : hosts_) {
    if (h.exit || !h.process || delivered(h) >= shown + 1) continue;
    if (h.process->stopped()) return &h;
    if (!late) late = &h;
  }
  return late;
}

std::string HostSet::stopped_note(const Host& h) {
  return h.process && h.process->stopped() ? " (stopped by a signal)" : "";
}

void HostSet::finish(milliseconds timeout) {
  const auto deadline = RunClock::now() + timeout;
  for (;;) {
    serve_channels();
    bool all = true;
    for (Host& h : hosts_) {
      if (!h.process) continue;  // not ours to wait for
      if (!h.exit) h.exit = h.process->poll();
      if (!h.exit) {
        all = false;
      } else if (!h.exit->ok()) {
        throw RunFault(
            fmt::format("pipeserver {} {} after the last frame", h.server, h.exit->describe()));
      }
    }
    if (all) return;
    if (RunClock::now() > deadline) throw RunFault("pipeservers did not end after the last frame");
    std::this_thread::sleep_for(milliseconds(2));
  }
}

void HostSet::request_stop() {
  for (Host& h : hosts_) {
    if (h.process && !h.exit) h.process->request_stop();
  }
}

void HostSet::shut_down() {
  for (Host& h : hosts_) {
    if (h.process && !h.exit) h.exit = h.process->terminate(milliseconds(500));
    h.process.reset();
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
