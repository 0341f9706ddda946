#include "live_mode.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "balance/desktop_messages.hpp"
#include "dvi_link/dvi_link.hpp"
#include "pipeserver/gl_context.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/viz_target.hpp"
#include "scene_vnc.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "viz_link/tile_sender.hpp"

namespace l2 {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// A scanned-out frame: fb_width x fb_height RGB, rows of fb_width * 3 bytes, in the DVI link's
// back frame or in the pipeserver's own.
struct FramePixels {
  std::uint8_t* data;
  std::size_t stride;
  std::uint8_t* at(int x, int y) const {
    return data + static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x) * 3;
  }
};

// The frame number goes into the stamp strip, a pixel the mesh reads and routes to no display
// (tile_layout.hpp): the run decodes it from the input (latency proof) and the displays show
// the picture unmarked. A framebuffer with no room for the strip marks its first tile's first
// pixel instead.
void stamp_frame(FramePixels fb, const PipeserverPlan& plan, int frame) {
  if (plan.tiles.empty()) return;
  const PackedTile& t = plan.tiles.front();
  std::uint8_t* p = plan.has_stamp_strip()
                        ? fb.at(plan.stamp_x, plan.rows[static_cast<std::size_t>(plan.stamp_row)].y)
                        : fb.at(t.fb_x, t.fb_y);
  p[0] = static_cast<std::uint8_t>(frame & 0xFF);
  p[1] = static_cast<std::uint8_t>((frame >> 8) & 0xFF);
  p[2] = static_cast<std::uint8_t>((frame >> 16) & 0xFF);
}

struct Report {
  std::FILE* file = nullptr;
  explicit Report(const std::string& path) {
    if (path.empty()) return;
    file = std::fopen(path.c_str(), "w");
    if (!file) throw std::runtime_error(fmt::format("cannot write report {}", path));
  }
  ~Report() {
    if (file) std::fclose(file);
  }
  void line(const std::string& text) {
    if (!file) return;
    std::fputs(text.c_str(), file);
    std::fflush(file);  // the run reads it even when we die later
  }
};

// The viz path: every tile of the frame, read back from the framebuffer, goes
// to the compositing server over TCP.
void send_tiles(TileSink& sender, FramePixels fb, const PipeserverPlan& plan, int frame) {
  for (const PackedTile& t : plan.tiles) {
    sender.send_tile(static_cast<std::uint32_t>(frame), viz_target(t.tile), fb.at(t.fb_x, t.fb_y),
                     fb.stride);
  }
  sender.finish_frame(static_cast<std::uint32_t>(frame),
                      static_cast<std::uint32_t>(plan.tiles.size()));
}

std::unique_ptr<TileSink> connect_viz(const std::string& address, int pipeserver, int display_count,
                                      std::optional<LinkCodec> codec) {
  if (address.empty()) return nullptr;
  const Endpoint at = parse_endpoint(address);
  viz::SenderOptions options;
  options.token = viz::token_from_environment();  // l2wall's run token (L2_VIZ_TOKEN)
  // Whole tiles go as TILE and TILE_EXT, straight from the framebuffer.
  if (codec != LinkCodec::Whole) options.codec = codec;
  return std::make_unique<TileSinkOf<viz::TileSender>>(
      viz::TileSender::connect(at.host, at.port, pipeserver, display_count, options));
}

// Frame k's tile times to the coordinator.
void send_times(ControlChannel& control, const Pipeserver& ps, int frame) {
  TimesMessage m{frame, ps.plan().pipeserver, {}, {}};
  for (double ms : ps.last_times().tile_ms) m.seconds.push_back(ms / 1000);
  if (ps.last_times().footprints.size() <= kMaxControlBatches)
    m.footprints = ps.last_times().footprints;
  control.send_line(encode(m));
}

// Frame `frame`'s layout from the coordinator, taken on by `ps`. Throws ControlError when none
// comes within `timeout` or it is for another frame, LayoutError when it cannot be planned.
void take_layout(ControlChannel& control, const Wall& wall, Pipeserver& ps, int frame,
                 std::chrono::milliseconds timeout) {
  const std::optional<std::string> line = control.receive_line(timeout);
  if (!line) {
    throw ControlError(fmt::format("control channel: no LAYOUT for frame {} within {} ms", frame,
                                   timeout.count()));
  }
  const LayoutMessage m = decode_layout(*line);
  if (m.frame != frame) {
    throw ControlError(
        fmt::format("control channel: LAYOUT for frame {} while frame {} is next", m.frame, frame));
  }
  ps.set_layout(plan_from_message(wall, m));
}

// Frame `frame`'s windows from the coordinator, placed in `scene`. Throws ControlError when
// none comes within `timeout` or it is for another frame.
void take_windows(ControlChannel& windows, Scene& scene, int frame,
                  std::chrono::milliseconds timeout) {
  const std::optional<std::string> line = windows.receive_line(timeout);
  if (!line) {
    throw ControlError(fmt::format("windows channel: no WINDOWS for frame {} within {} ms", frame,
                                   timeout.count()));
  }
  const WindowsMessage m = decode_windows(*line);
  if (m.frame != frame) {
    throw ControlError(fmt::format("windows channel: WINDOWS for frame {} while frame {} is next",
                                   m.frame, frame));
  }
  std::vector<WindowPlacement> placed;
  for (const WindowPlace& w : m.windows) placed.push_back({w.id, w.on_canvas});
  scene.place_windows(placed);
}

// One desktop's DESKTOP line and its RECTs for frame `frame`, taken into `scene`. Throws
// ControlError when none comes within `timeout`, it is for another frame or its pixels are not
// the desktop's.
void take_desktop(ControlChannel& channel, detail::DesktopScene& scene, int frame,
                  std::chrono::milliseconds timeout) {
  const auto line = [&] {
    std::optional<std::string> l = channel.receive_line(timeout);
    if (!l)
      throw ControlError(
          fmt::format("desktop: nothing for frame {} within {} ms from the run "
                      "({})",
                      frame, timeout.count(), scene.address()));
    return *l;
  };
  const DesktopMessage m = decode_desktop(line());
  if (m.frame != frame)
    throw ControlError(
        fmt::format("desktop: DESKTOP for frame {} while frame {} is next", m.frame, frame));
  scene.hold(m.width, m.height, m.regions);
  for (int i = 0; i < m.rects; ++i) {
    const DesktopRect r = decode_desktop_rect(line());
    try {
      scene.put(r.rect, r.rgb.data());
    } catch (const std::invalid_argument& e) {
      throw ControlError(e.what());
    }
  }
}

// Frame `frame`'s desktops from the coordinator (desktop_messages.hpp), asked for with WANT and
// taken in at once: the coordinator answers every WANT as it comes, so a large answer never
// waits for this pipeserver to finish a READY wait. A session's answer is its WINDOWS line
// first, then each desktop's lines, in the order of scene.desktops().
void take_desktops(ControlChannel& channel, Scene& scene, int pipeserver, int frame,
                   std::chrono::milliseconds timeout) {
  channel.send_line(encode(WantMessage{frame, pipeserver}));
  const bool session = dynamic_cast<detail::DesktopScene*>(&scene) == nullptr;
  if (session) take_windows(channel, scene, frame, timeout);
  for (detail::DesktopScene* d : scene.desktops()) take_desktop(channel, *d, frame, timeout);
}

// The SYNC? retries (or, for SWAPPED, the timeouts) a pipeserver allows the swap of `frame`. The
// swap of frame 0 also waits for every other pipeserver's start-up (GL context, first render),
// which on a loaded machine can take seconds: that wait gets more, whichever path paces the
// pipeserver and whether it is the run's last frame or not.
int swap_retries(const LiveOptions& o, int frame) {
  return frame == 0 ? std::max(o.ready_retries, 30) : o.ready_retries;
}

}  // namespace

MakeLiveLinks shared_memory_links(const std::string& link, const std::string& backchannel) {
  return [link, backchannel](const TileLayout&, const PipeserverPlan& plan) {
    LiveLinks links;
    links.link =
        std::make_unique<DviLinkWriter>(DviLinkWriter::create(link, plan.fb_width, plan.fb_height));
    auto port = std::make_shared<SerialPort>(SerialPort::open(backchannel));
    links.channel = std::make_unique<BackChannel>(*port);
    links.keeps = port;
    return links;
  };
}

int run_live_mode(const LiveOptions& o) {
  const Wall wall = o.wall.empty() ? default_wall() : load_wall(o.wall);
  const TileLayout layout = plan_layout(wall);
  auto scene = make_scene(o.scene, o.scene_options);
  Report report(o.report);
  // Before the first context: the run's summary says what each pipeserver renders with.
  report.line(fmt::format("renderer {}\n", use_renderer(o.renderer).line()));
  Pipeserver ps(layout, o.pipeserver);
  const PipeserverPlan& plan = ps.plan();
  LiveLinks links = o.links ? o.links(layout, plan) : LiveLinks{};
  DviSender* const link = links.link.get();
  ReadyChannel* const channel = links.channel.get();
  const std::unique_ptr<TileSink> sender =
      links.tiles
          ? std::move(links.tiles)
          : connect_viz(o.viz, o.pipeserver, static_cast<int>(wall.displays.size()), o.link_codec);
  const std::chrono::milliseconds timeout(o.ready_timeout_ms);
  // A vnc scene, or a session's vnc windows, show the desktop the coordinator sends on the
  // windows channel.
  const bool desktop = !scene->desktops().empty();
  if (desktop && !o.windows)
    throw ControlError(fmt::format(
        "--scene {} shows the desktop l2wall run sends (--windows-fd): run it through l2wall run",
        o.scene));
  // Frame 0's waits for every other pipeserver's start-up too.
  if (desktop && o.frames > 0)
    take_desktops(*o.windows, *scene, o.pipeserver, 0, timeout * (swap_retries(o, 0) + 1));

  for (int k = 0; k < o.frames; ++k) {
    const auto t0 = Clock::now();
    // With a link the frame is scanned out straight into its back frame: no copy to make.
    // Stamped and sent to the compositing server while every tile is whole at its packed place,
    // before the DEPTH rows go sparse (pipeserver.hpp); the stamp's pixel stays where it is.
    const auto dense = [&](std::span<std::uint8_t> frame) {
      const FramePixels fb{frame.data(), static_cast<std::size_t>(plan.fb_width) * 3};
      stamp_frame(fb, plan, k);
      if (sender) send_tiles(*sender, fb, plan, k);
    };
    if (link) {
      ps.render_frame(k, *scene, link->back_frame(), dense);
    } else {
      ps.render_frame(k, *scene, dense);
    }
    const double render_ms = ms_since(t0);
    // Sent before the READY wait, so the coordinator plans the next frame meanwhile.
    if (o.control) send_times(*o.control, ps, k);
    if (desktop && k + 1 < o.frames)
      take_desktops(*o.windows, *scene, o.pipeserver, k + 1, timeout * (o.ready_retries + 1));
    else if (o.windows && k + 1 < o.frames)
      o.windows->send_line(encode(WantMessage{k + 1, o.pipeserver}));
    const auto t1 = Clock::now();
    int retries = 0;
    const int retries_allowed = swap_retries(o, k - 1);
    if (k > 0 && channel) {  // spec §6.1: the first swap does not wait
      const Result<ReadyAck> r =
          channel->wait_ready(static_cast<std::uint64_t>(k - 1), timeout, retries_allowed);
      if (!r.ok()) {
        std::fprintf(stderr, "pipeserver %d: frame %d: %s\n", o.pipeserver, k, r.reason().c_str());
        return kExitNoReady;
      }
      retries = r->retries;
    }
    // The compositing server's SWAPPED paces the vizserver path (alone, instead of READY). With
    // both paths it is read too: a pipeserver that exits with SWAPPED unread resets the connection,
    // and the server could lose tiles it had not read yet.
    if (k > 0 && sender) {
      sender->wait_swapped(static_cast<std::uint32_t>(k - 1), timeout * (retries_allowed + 1));
    }
    const double wait_ms = ms_since(t1);
    if (link) link->publish();
    if (o.control && k + 1 < o.frames) {
      take_layout(*o.control, wall, ps, k + 1, timeout * (o.ready_retries + 1));
    }
    if (o.windows && !desktop && k + 1 < o.frames)
      take_windows(*o.windows, *scene, k + 1, timeout * (o.ready_retries + 1));
    // The bucketing figures too: how many tiles a batch lands in, which a large model drives up.
    const BucketStats& b = ps.last_times().buckets;
    report.line(fmt::format(
        "frame {} render_ms {:.3f} wait_ms {:.3f} retries {} batches {} tile_draws {} overlap "
        "{:.2f}\n",
        k, render_ms, wait_ms, retries, b.batches, b.tile_draws, b.overlap_factor()));
  }
  // Stay until the last frame is taken in and complete: the run reads our link until then.
  const int last_retries = swap_retries(o, o.frames - 1);
  if (o.frames > 0 && channel) {
    const Result<ReadyAck> r =
        channel->wait_ready(static_cast<std::uint64_t>(o.frames - 1), timeout, last_retries);
    if (!r.ok()) {
      std::fprintf(stderr, "pipeserver %d: last frame %d: %s\n", o.pipeserver, o.frames - 1,
                   r.reason().c_str());
      return kExitNoReady;
    }
  }
  if (o.frames > 0 && sender) {
    sender->wait_swapped(static_cast<std::uint32_t>(o.frames - 1), timeout * (last_retries + 1));
  }
  if (channel) {
    const BackChannelCounts& c = channel->counts();
    report.line(fmt::format("done resyncs {} noise_bytes {} sync_sent {} timeouts {}\n",
                            c.parser.resyncs, c.parser.noise_bytes, c.sync_sent, c.wait_timeouts));
  } else {
    report.line("done (vizserver path only, no back-channel)\n");
  }
  return 0;
}

}  // namespace l2
