#include "live_run.hpp"

#include <fmt/format.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "display_compare.hpp"
#include "dvi_link/dvi_link.hpp"
#include "dvi_link/refresh_clock.hpp"
#include "frame_stamp.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/emulator.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/pty_pair.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "vizserver/compositing_server.hpp"
#include "wall_picture.hpp"

namespace l2 {

KeepSet parse_keep(const std::string& text) {
  KeepSet keep;
  if (text == "every") {
    keep.every = true;
  } else if (text == "last") {
    keep.last = true;
  } else if (text != "none") {
    if (text.empty() || text.back() == ',')
      throw std::invalid_argument(fmt::format("--keep: '{}' ends without a frame number", text));
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
      std::size_t used = 0;
      int k = -1;
      try {
        k = std::stoi(item, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != item.size() || item.empty() || k < 0)
        throw std::invalid_argument(
            fmt::format("--keep: '{}' is not every, last, none or a frame number", item));
      keep.frames.insert(k);
    }
  }
  return keep;
}

namespace {

using Clock = std::chrono::steady_clock;

// Ctrl-C or SIGTERM: the run stops through its normal fault path, so the hosts are ended and
// their shared memory removed instead of left behind.
volatile sig_atomic_t g_stop_signal = 0;
extern "C" void on_stop_signal(int signal) {
  g_stop_signal = signal;
}
void catch_stop_signals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}
using std::chrono::milliseconds;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// A failure of the run that names the host and the frame; the run stops on it.
class RunFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One pipeserver: its process, DVI link and back-channel. Members are destroyed in reverse:
// the process is ended and reaped before the link reader and the pty go away.
struct Host {
  int server = 0;
  std::string link_name;
  std::string report_path;
  std::unique_ptr<PtyPair> pty;
  std::unique_ptr<BackChannel> channel;
  std::optional<DviLinkReader> reader;
  std::optional<ChildProcess> process;
  std::optional<ExitStatus> exit;
  std::uint64_t sequence = 0;  // frames published so far
  int accepted = -1;           // the frame number of the last new frame the emulator took in
  // Where the frame stamp is: framebuffer pixel and the display pixel it lands on.
  int fb_x = 0, fb_y = 0, display = 0, dx = 0, dy = 0;
  // Fault injection: a READY held back until the host asks with SYNC?.
  std::optional<int> held_ready;
};

struct FrameRecord {
  std::uint64_t in_refresh = 0;    // refresh at which its last input was taken in
  std::uint64_t swap_refresh = 0;  // refresh at which it reached every display
  Clock::time_point in_time{}, swap_time{};
  double route_ms = 0;    // emulator time of the refreshes that routed this frame
  double writing_ms = 0;  // picture writing of the run up to this frame's swap
  bool shown = false;
};

struct HostFrame {
  double render_ms = 0, wait_ms = 0;
  int retries = 0;
};
struct HostLog {
  std::vector<HostFrame> frames;
  std::string done;  // the host's back-channel counts
};

HostLog read_host_log(const std::string& path, int frames) {
  HostLog log;
  log.frames.resize(static_cast<std::size_t>(frames));
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    int k = 0, retries = 0;
    double render = 0, wait = 0;
    if (std::sscanf(line.c_str(), "frame %d render_ms %lf wait_ms %lf retries %d", &k, &render,
                    &wait, &retries) == 4 &&
        k >= 0 && k < frames) {
      log.frames[static_cast<std::size_t>(k)] = {render, wait, retries};
    } else if (line.rfind("done ", 0) == 0) {
      log.done = line.substr(5);
    }
  }
  return log;
}

// Adds the time of a scope to a total: PNG writing is not part of the frame rate.
struct Timed {
  double& total;
  Clock::time_point t0 = Clock::now();
  explicit Timed(double& sum) : total(sum) {}
  ~Timed() { total += ms_between(t0, Clock::now()); }
  Timed(const Timed&) = delete;
  Timed& operator=(const Timed&) = delete;
};

int frames_reported(const std::string& host_log) {
  std::ifstream in(host_log);
  int frames = 0;
  for (std::string line; std::getline(in, line);) frames += line.rfind("frame ", 0) == 0;
  return frames;
}

class LiveRun {
 public:
  explicit LiveRun(const RunOptions& o)
      : o_(o),
        keep_(parse_keep(o.keep)),
        wall_(o.wall.empty() ? default_wall() : load_wall(o.wall)),
        layout_(plan_layout(wall_)),
        emulator_(emulator_config()),
        records_(static_cast<std::size_t>(o.frames)) {}

  ~LiveRun() { shut_down(); }

  int run() {
    if (o_.path != "dvi" && o_.path != "vizserver" && o_.path != "both")
      throw std::invalid_argument("--path: expected dvi, vizserver or both, got " + o_.path);
    if (o_.compare && o_.path != "both") throw std::invalid_argument("--compare needs --path both");
    std::filesystem::create_directories(o_.out);
    start_viz();
    start_hosts();
    if (dvi()) {
      open_links();
      loop();
    } else {
      viz_loop();
    }
    finish_hosts();
    if (viz_) {
      viz_->wait_finished(milliseconds(5000));
      viz_->stop();
    }
    write_report();
    return latency_ok_ ? 0 : 1;
  }

  // After a fault: what the displays show now goes to DIR/fault/, then everything stops.
  void save_displays_after_fault() {
    try {
      write_displays(std::filesystem::path(o_.out) / "fault");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: could not save the displays: %s\n", e.what());
    }
  }
  int last_shown() const { return shown_ - 1; }

  // Ends every host (SIGTERM, then SIGKILL), reaps it, and removes links a dead host left.
  void shut_down() {
    if (viz_) viz_->stop();
    for (Host& h : hosts_) {
      if (h.process && !h.exit) h.exit = h.process->terminate(milliseconds(500));
      h.process.reset();
      h.reader.reset();
      try {
        remove_stale(h.link_name);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "l2wall: %s\n", e.what());
      }
    }
  }

 private:
  EmulatorConfig emulator_config() const {
    EmulatorConfig config;
    for (const Display& d : wall_.displays)
      config.displays.push_back({d.id, d.width, d.height, d.swap_group});
    config.mesh = Mesh::fit(wall_.server_count, static_cast<int>(wall_.displays.size()),
                            {wall_.board_max_width, wall_.board_max_height});
    config.workers = o_.threads;
    return config;
  }

  bool dvi() const { return o_.path != "vizserver"; }

  // The compositing server of the vizserver path runs in this process, on its own thread.
  void start_viz() {
    if (o_.path == "dvi") return;
    viz::ServerOptions options;
    for (const Display& d : wall_.displays) options.display_sizes.emplace_back(d.width, d.height);
    options.servers = wall_.server_count;
    options.accept_timeout = milliseconds(o_.start_timeout_ms);
    options.stall_timeout = milliseconds(0);  // a hang is ours to name (check_stall)
    options.keep_frames = 16;
    viz_ = std::make_unique<viz::CompositingServer>(options);
    viz_->start();
  }

  // The frame `frame` of the vizserver path; polls so that a dead host is still noticed.
  viz::FramePtr viz_frame(int frame) {
    for (;;) {
      try {
        return viz_->wait_frame(static_cast<std::uint32_t>(frame), milliseconds(20));
      } catch (const viz::VizError& e) {
        if (const auto failure = viz_->failure()) throw RunFault("vizserver path: " + *failure);
        if (viz_->last_swapped() && *viz_->last_swapped() >= static_cast<std::uint32_t>(frame))
          throw RunFault(fmt::format("vizserver path: frame {}: {}", frame, e.what()));
      }
      check_hosts();
      check_stall();
      serve_channels();
    }
  }

  // --path vizserver: the compositing server's swaps are the display frames.
  void viz_loop() {
    start_ = Clock::now();
    last_swap_ = start_;
    latency_measured_ = false;
    while (shown_ < o_.frames) {
      const viz::FramePtr f = viz_frame(shown_);
      const auto now = Clock::now();
      // Like the DVI path, the clock starts once every host has delivered its first frame.
      if (shown_ == 0) start_ = now;
      FrameRecord& r = records_[static_cast<std::size_t>(shown_)];
      r.shown = true;
      r.swap_time = now;
      r.in_time = now;
      r.writing_ms = writing_ms_;
      if (keep_.keeps(shown_, o_.frames))
        write_viz_displays(std::filesystem::path(o_.out) / fmt::format("frame-{}", shown_), *f, "");
      ++shown_;
      last_swap_ = now;
      progress(now);
    }
  }

  void write_viz_displays(const std::filesystem::path& dir, const viz::ComposedFrame& f,
                          const std::string& suffix) {
    const Timed timed(writing_ms_);
    std::filesystem::create_directories(dir);
    for (std::size_t i = 0; i < f.displays.size(); ++i)
      write_png(dir / fmt::format("display-{}{}.png", i, suffix), f.displays[i]);
    write_png(dir / fmt::format("wall{}.png", suffix),
              compose_wall_picture(wall_, [&f](int id) -> const RgbImage& {
                return f.displays.at(static_cast<std::size_t>(id));
              }));
  }

  // --path both --compare: the two paths must give the same displays, byte for byte.
  void compare_paths(int frame) {
    const viz::FramePtr f = viz_frame(frame);
    for (const Display& d : wall_.displays) {
      const RgbImage& via_dvi = emulator_.shown(d.id);
      RgbImage tampered;
      const RgbImage* via_viz_ptr = &f->displays.at(static_cast<std::size_t>(d.id));
      if (frame == o_.inject_mismatch && d.id == 0) {
        // Fault injection: one pixel off, to show what a mismatch looks like.
        tampered = *via_viz_ptr;
        const Rgb p = tampered.at(tampered.width() / 2, tampered.height() / 2);
        tampered.set(tampered.width() / 2, tampered.height() / 2,
                     Rgb{static_cast<std::uint8_t>(p.r ^ 0x80), p.g, p.b});
        via_viz_ptr = &tampered;
      }
      const RgbImage& via_viz = *via_viz_ptr;
      const DisplayDiff diff = compare_displays(via_dvi, via_viz);
      ++compared_displays_;
      if (diff.identical()) continue;
      const auto dir = std::filesystem::path(o_.out) / fmt::format("mismatch-frame-{}", frame);
      std::filesystem::create_directories(dir);
      write_png(dir / fmt::format("display-{}-dvi.png", d.id), via_dvi);
      write_png(dir / fmt::format("display-{}-vizserver.png", d.id), via_viz);
      write_png(dir / fmt::format("display-{}-diff.png", d.id), diff.picture);
      throw RunFault(fmt::format(
          "frame {}: display {} differs between the DVI and vizserver paths in {} pixels; "
          "both pictures and the difference are in {}",
          frame, d.id, diff.differing_pixels, dir.string()));
    }
  }

  void start_hosts() {
    hosts_.resize(static_cast<std::size_t>(wall_.server_count));
    for (int i = 0; i < wall_.server_count; ++i) {
      Host& h = hosts_[static_cast<std::size_t>(i)];
      h.server = i;
      h.link_name = dvi_link_name(fmt::format("in{}", i));
      h.report_path = (std::filesystem::path(o_.out) / fmt::format("host-{}.log", i)).string();
      std::filesystem::remove(h.report_path);
      h.pty = std::make_unique<PtyPair>(PtyPair::open());
      h.channel = std::make_unique<BackChannel>(h.pty->master());
      const ServerPlan& plan = layout_.servers.at(static_cast<std::size_t>(i));
      if (!plan.tiles.empty()) {
        const PackedTile& t = plan.tiles.front();
        h.fb_x = t.fb_x;
        h.fb_y = t.fb_y;
        h.display = t.tile.display;
        h.dx = t.tile.on_display.x;
        h.dy = t.tile.on_display.y;
      }
      std::vector<std::string> argv{
          o_.pipeserver,     "--live",          "--server",
          std::to_string(i), "--frames",        std::to_string(o_.frames),
          "--scene",         o_.scene,          "--report",
          h.report_path,     "--ready-timeout", std::to_string(o_.ready_timeout_ms)};
      if (dvi()) {
        for (const std::string& a : {std::string("--link"), h.link_name,
                                     std::string("--backchannel"), h.pty->slave_path()})
          argv.push_back(a);
      }
      if (viz_) {
        argv.push_back("--viz");
        argv.push_back(fmt::format("127.0.0.1:{}", viz_->port()));
      }
      if (!o_.wall.empty()) {
        argv.push_back("--wall");
        argv.push_back(o_.wall);
      }
      h.process.emplace(std::move(argv));
    }
  }

  // A host that ended: fine once every frame is on the displays, a fault before that.
  void check_hosts() {
    if (g_stop_signal) {
      throw RunFault(fmt::format(
          "stopped by signal {} ({}) at frame {}; the displays keep frame {}",
          static_cast<int>(g_stop_signal), strsignal(g_stop_signal), shown_, shown_ - 1));
    }
    for (Host& h : hosts_) {
      if (h.exit || !h.process) continue;
      if (auto status = h.process->poll()) {
        h.exit = status;
        if (!status->ok() || shown_ < o_.frames) {
          throw RunFault(fmt::format(
              "pipeserver {} (pid {}) {} while rendering frame {}; the displays keep frame {}",
              h.server, h.process->pid(), status->describe(), h.sequence, shown_ - 1));
        }
      }
    }
  }

  void open_links() {
    const auto deadline = Clock::now() + milliseconds(o_.start_timeout_ms);
    for (;;) {
      check_hosts();
      bool all = true;
      for (Host& h : hosts_) {
        if (!h.reader) {
          try {
            h.reader.emplace(DviLinkReader::open(h.link_name));
          } catch (const DviLinkError&) {
            // not created yet
          }
        }
        if (!h.reader || !h.reader->latest()) all = false;
      }
      // The emulator starts once every link carries a signal: an input without one feeds no
      // group, so a group would otherwise swap with only the hosts that happened to be first.
      if (all) return;
      if (Clock::now() > deadline) {
        std::string missing;
        for (const Host& h : hosts_)
          if (!h.reader || h.sequence == 0) missing += fmt::format(" {}", h.server);
        throw RunFault(fmt::format("no first frame within {} ms from pipeserver(s){}",
                                   o_.start_timeout_ms, missing));
      }
      std::this_thread::sleep_for(milliseconds(5));
    }
  }

  // Takes in every link; true when some link has a frame not seen before.
  bool take_in(std::vector<InputFrame>& inputs) {
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

  void loop() {
    std::vector<InputFrame> inputs(hosts_.size());
    RefreshClock clock(o_.refresh_hz);
    bool swap_due = false;
    start_ = Clock::now();
    last_swap_ = start_;
    while (shown_ < o_.frames) {
      if (o_.refresh_hz > 0) clock.wait_next();
      check_hosts();
      const bool fresh = take_in(inputs);
      serve_channels();
      // As fast as possible still means "when there is something to do": re-reading unchanged
      // links would only take CPU from the hosts.
      if (o_.refresh_hz == 0 && !fresh && !swap_due) {
        check_stall();
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        continue;
      }
      const auto t0 = Clock::now();
      const Emulator::Tick& tick = emulator_.tick(inputs);
      const double route_ms = ms_between(t0, Clock::now());
      ++refreshes_;
      note_new_frames(tick, inputs, route_ms, t0);
      swap_due = !tick.completed_groups.empty();
      if (!tick.swapped_groups.empty()) on_swap(tick);
      check_stall();
    }
  }

  void note_new_frames(const Emulator::Tick& tick, const std::vector<InputFrame>& inputs,
                       double route_ms, Clock::time_point t0) {
    for (std::size_t i = 0; i < hosts_.size(); ++i) {
      if (tick.kinds.size() <= i || tick.kinds[i] != FrameKind::New) continue;
      Host& h = hosts_[i];
      h.accepted = decode_stamp(inputs[i].row(h.fb_y) + h.fb_x * 3);
      if (h.accepted < 0 || h.accepted >= o_.frames)
        throw RunFault(
            fmt::format("pipeserver {}: frame stamp {} out of range", h.server, h.accepted));
      FrameRecord& r = records_[static_cast<std::size_t>(h.accepted)];
      r.route_ms += route_ms;
      r.in_refresh = tick.index;  // the last input taken in decides
      r.in_time = t0;
    }
  }

  // Reads from the displays which frame each host's stamp shows: measured, not assumed.
  int frame_on_displays(const Host& h) const {
    const RgbImage& shown = emulator_.shown(h.display);
    return decode_stamp(shown.row(h.dy).data() + h.dx * 3);
  }

  void on_swap(const Emulator::Tick& tick) {
    const auto now = Clock::now();
    int lowest = o_.frames;
    for (const Host& h : hosts_) lowest = std::min(lowest, frame_on_displays(h));
    // READY for the frame the emulator accepted from each host now on the displays.
    for (int i : tick.ready_inputs) {
      Host& h = hosts_[static_cast<std::size_t>(i)];
      if (i == 0 && h.accepted == o_.drop_ready) {
        h.held_ready = h.accepted;  // lost on the line: the host must ask with SYNC?
        ++dropped_readies_;
        continue;
      }
      h.channel->send_ready(static_cast<std::uint64_t>(h.accepted));
    }
    while (shown_ <= lowest && shown_ < o_.frames) {
      FrameRecord& r = records_[static_cast<std::size_t>(shown_)];
      r.shown = true;
      r.swap_refresh = tick.index;
      r.swap_time = now;
      r.writing_ms = writing_ms_;
      const long latency = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
      if (latency != 1) {
        latency_ok_ = false;
        std::fprintf(stderr, "\nl2wall: frame %d: latency %ld refreshes, expected 1\n", shown_,
                     latency);
      }
      if (o_.compare) compare_paths(shown_);
      if (keep_.keeps(shown_, o_.frames)) {
        const auto dir = std::filesystem::path(o_.out) / fmt::format("frame-{}", shown_);
        write_displays(dir);
        if (viz_) write_viz_displays(dir, *viz_frame(shown_), "-vizserver");
      }
      if (shown_ == o_.noise_after) inject_noise();
      ++shown_;
      last_swap_ = now;
    }
    progress(now);
  }

  void progress(Clock::time_point now) const {
    if (!o_.progress) return;
    const double s = ms_between(start_, now) / 1000.0;
    std::fprintf(stderr, "\rl2wall: frame %d/%d on the displays, %.1f fps", shown_, o_.frames,
                 s > 0 ? shown_ / s : 0.0);
    std::fflush(stderr);
  }

  void inject_noise() {
    static const char kNoise[] = "RE\x01\xffz9 READY 12 ZZ\r\nSYNC? 0\x7f\x80 R";
    for (Host& h : hosts_) {
      h.pty->master().write_some(std::span<const std::uint8_t>(
          reinterpret_cast<const std::uint8_t*>(kNoise), sizeof kNoise - 1));
      noise_bytes_ += sizeof kNoise - 1;
    }
  }

  void serve_channels() {
    if (!dvi()) return;
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

  void check_stall() {
    const auto now = Clock::now();
    // Before the first swap the hosts may still be starting (GL context, first render).
    const int limit_ms = shown_ == 0 ? o_.start_timeout_ms : o_.stall_timeout_ms;
    if (ms_between(last_swap_, now) < limit_ms) return;
    std::string culprits;
    for (const Host& h : hosts_) {
      // A host that has not delivered the frame the displays wait for is the one that hangs:
      // on the DVI path its link says so, on the vizserver path its report (one line per frame).
      const std::uint64_t delivered =
          dvi() ? h.sequence : static_cast<std::uint64_t>(frames_reported(h.report_path));
      if (delivered < static_cast<std::uint64_t>(shown_) + 1)
        culprits += fmt::format("{}pipeserver {} (pid {})", culprits.empty() ? "" : ", ", h.server,
                                h.process ? h.process->pid() : -1);
    }
    throw RunFault(
        fmt::format("no display swap for {} ms: {} did not deliver frame {}; the "
                    "displays keep frame {}",
                    limit_ms, culprits.empty() ? "no host" : culprits, shown_, shown_ - 1));
  }

  void finish_hosts() {
    const auto deadline = Clock::now() + milliseconds(10000);
    for (;;) {
      serve_channels();
      bool all = true;
      for (Host& h : hosts_) {
        if (!h.exit) h.exit = h.process->poll();
        if (!h.exit) {
          all = false;
        } else if (!h.exit->ok()) {
          throw RunFault(
              fmt::format("pipeserver {} {} after the last frame", h.server, h.exit->describe()));
        }
      }
      if (all) return;
      if (Clock::now() > deadline) throw RunFault("pipeservers did not end after the last frame");
      std::this_thread::sleep_for(milliseconds(2));
    }
  }

  void write_displays(const std::filesystem::path& dir) {
    if (!dvi()) return;  // the vizserver-only path keeps its frames as it goes
    const Timed timed(writing_ms_);
    std::filesystem::create_directories(dir);
    for (const Display& d : wall_.displays)
      write_png(dir / fmt::format("display-{}.png", d.id), emulator_.shown(d.id));
    write_png(dir / "wall.png", compose_wall_picture(wall_, [this](int id) -> const RgbImage& {
                return emulator_.shown(id);
              }));
  }

  void write_report() {
    std::vector<HostLog> logs;
    for (const Host& h : hosts_) logs.push_back(read_host_log(h.report_path, o_.frames));
    const auto csv_path = std::filesystem::path(o_.out) / "report.csv";
    std::ofstream csv(csv_path);
    csv << "frame,in_refresh,swap_refresh,latency_frames,route_ms,swap_ms";
    for (const Host& h : hosts_)
      csv << fmt::format(",render_ms_{0},ready_wait_ms_{0},sync_retries_{0}", h.server);
    csv << "\n";
    long min_latency = 1 << 30, max_latency = -1;
    for (int k = 0; k < o_.frames; ++k) {
      const FrameRecord& r = records_[static_cast<std::size_t>(k)];
      const long latency = static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
      min_latency = std::min(min_latency, latency);
      max_latency = std::max(max_latency, latency);
      if (dvi()) {
        csv << fmt::format("{},{},{},{},{:.3f},{:.3f}", k, r.in_refresh, r.swap_refresh, latency,
                           r.route_ms, ms_between(r.in_time, r.swap_time));
      } else {
        csv << fmt::format("{},,,n/a,,", k);  // no emulator on the vizserver path
      }
      for (const HostLog& log : logs) {
        const HostFrame& f = log.frames[static_cast<std::size_t>(k)];
        csv << fmt::format(",{:.3f},{:.3f},{}", f.render_ms, f.wait_ms, f.retries);
      }
      csv << "\n";
    }
    // Up to the last swap: writing the kept PNGs afterwards is not part of the frame rate.
    const double seconds =
        (ms_between(start_, records_.back().swap_time) - records_.back().writing_ms) / 1000.0;
    const std::string pace =
        !dvi() ? std::string("no emulator refresh: the compositing server swaps")
               : fmt::format("{} refreshes at {}", refreshes_,
                             o_.refresh_hz > 0 ? fmt::format("{:g} Hz", o_.refresh_hz)
                                               : std::string("full speed"));
    std::string summary = fmt::format(
        "l2wall run: {} frames on {} displays from {} pipeservers in {:.2f} s: {:.1f} fps ({})\n"
        "latency: {} frame{} (display refresh j shows the input frame taken in at refresh j-1), "
        "measured from the frame stamps on the displays: min {}, max {}\n",
        o_.frames, wall_.displays.size(), hosts_.size(), seconds,
        seconds > 0 ? o_.frames / seconds : 0.0, pace, max_latency, max_latency == 1 ? "" : "s",
        min_latency, max_latency);
    if (!latency_measured_) {
      summary = summary.substr(0, summary.find("latency: ")) +
                "latency: not measured on the vizserver path (no DVI link, no refresh)\n";
    }
    if (o_.path != "dvi") summary += fmt::format("paths: {}\n", o_.path);
    if (o_.compare) {
      summary += fmt::format(
          "compare: {} display pictures identical byte for byte on the DVI and vizserver "
          "paths\n",
          compared_displays_);
    }
    if (noise_bytes_ || dropped_readies_) {
      summary += fmt::format("faults injected: {} noise bytes, {} READY dropped\n", noise_bytes_,
                             dropped_readies_);
    }
    for (std::size_t i = 0; i < hosts_.size(); ++i) {
      summary += fmt::format("back-channel host {}: {}\n", i,
                             logs[i].done.empty() ? "no report" : logs[i].done);
    }
    summary += fmt::format("report: {}\n", csv_path.string());
    if (o_.progress) std::fputs("\n", stderr);
    std::fputs(summary.c_str(), stdout);
    std::ofstream(std::filesystem::path(o_.out) / "summary.txt") << summary;
  }

  RunOptions o_;
  KeepSet keep_;
  Wall wall_;
  TileLayout layout_;
  Emulator emulator_;
  std::deque<Host> hosts_;  // a deque: hosts never move, the back-channels refer to their ptys
  std::vector<FrameRecord> records_;
  int shown_ = 0;  // frames 0 .. shown_-1 have reached every display
  std::uint64_t refreshes_ = 0;
  bool latency_ok_ = true;
  std::uint64_t noise_bytes_ = 0, dropped_readies_ = 0, compared_displays_ = 0;
  bool latency_measured_ = true;
  double writing_ms_ = 0;                        // spent writing kept pictures during the run
  std::unique_ptr<viz::CompositingServer> viz_;  // the vizserver path, when asked for
  Clock::time_point start_{}, last_swap_{};
};

}  // namespace

int run_wall(const RunOptions& options) {
  catch_stop_signals();
  std::unique_ptr<LiveRun> run;
  try {
    run = std::make_unique<LiveRun>(options);
    return run->run();
  } catch (const RunFault& e) {
    if (options.progress) std::fputs("\n", stderr);
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    if (run) {
      run->save_displays_after_fault();
      std::fprintf(stderr, "l2wall: displays as they were: %s/fault/\n", options.out.c_str());
      run->shut_down();
    }
    return 1;
  } catch (const std::exception& e) {
    if (options.progress) std::fputs("\n", stderr);
    std::fprintf(stderr, "l2wall: %s\n", e.what());
    return 1;
  }
}

}  // namespace l2
