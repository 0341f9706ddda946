#include "live_page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "control_page/access_token.hpp"
#include "image/turn.hpp"
#include "l2wall/path_choice.hpp"
#include "run_stats.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

// A few pictures a second is what a person watching needs; more would take the run's time.
constexpr milliseconds kPublishEvery{250};
// The page reads its state a few times a second; a reader this long silent has gone away.
constexpr milliseconds kWatchedWithin{3000};
constexpr std::size_t kRecentFrames = 60;
constexpr std::size_t kEventsKept = 50;

HttpAddress address_of(const RunOptions& o) {
  const Result<HttpAddress> a = parse_http_address(o.http);
  if (!a.ok()) throw std::invalid_argument("--http: " + a.reason());
  return *a;
}

template <class T>
void keep_last(std::vector<T>& v, std::size_t n) {
  if (v.size() > n) v.erase(v.begin(), v.end() - static_cast<std::ptrdiff_t>(n));
}

}  // namespace

RunState wall_state(const Wall& wall) {
  RunState s;
  s.wall_name = wall.name;
  s.canvas_width = wall.canvas_width;
  s.canvas_height = wall.canvas_height;
  for (const Display& d : wall.displays) {
    const Rect r = d.on_canvas();
    s.displays.push_back({d.id, r.x, r.y, r.w, r.h, d.swap_group, d.orientation});
  }
  return s;
}

void take_log_line(PagePipeserver& p, const PipeserverLogLine& line) {
  if (line.kind == PipeserverLogLine::Kind::Frame) {
    p.recent.push_back({line.frame, line.render_ms, line.wait_ms, line.retries});
    keep_last(p.recent, kRecentFrames);
  }
  if (line.kind == PipeserverLogLine::Kind::Done) p.back_channel = line.done;
  if (line.kind == PipeserverLogLine::Kind::Renderer) p.renderer = line.renderer;
}

std::vector<PageTile> page_tiles(const TileLayout& layout) {
  std::vector<PageTile> tiles;
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    const Rect& r = layout.tiles[i].on_canvas;
    tiles.push_back({r.x, r.y, r.w, r.h, layout.tile_pipeserver[i]});
  }
  return tiles;
}

std::vector<PageTile> page_tiles(const LayoutMessage& layout) {
  std::vector<PageTile> tiles;
  for (std::size_t i = 0; i < layout.tiles.size() && i < layout.pipeservers.size(); ++i) {
    const Rect& r = layout.tiles[i];
    tiles.push_back({r.x, r.y, r.w, r.h, layout.pipeservers[i]});
  }
  return tiles;
}

LivePage::LivePage(const RunOptions& o, const Wall& wall, bool stoppable) {
  const HttpAddress address = address_of(o);
  server_ = std::make_unique<ControlServer>(address, make_access_token());
  state_ = wall_state(wall);
  state_.path = path_choice_name(o.path);
  state_.frames_planned = o.frames;
  state_.stoppable = stoppable;
  // Published before the URL is printed: whoever follows it reads the run's state, never the
  // server's empty one.
  server_->publish(state_);
  std::fprintf(stderr, "l2wall: control page: %s%s\n", server_->url().c_str(),
               address.loopback() ? ""
                                  : " (reachable beyond this machine: the token is the only "
                                    "lock, and the traffic is not encrypted)");
}

void LivePage::watch_pipeservers(const std::vector<std::string>& logs,
                                 const std::vector<std::string>& places) {
  logs_.clear();
  state_.pipeservers.clear();
  for (std::size_t i = 0; i < logs.size(); ++i) {
    logs_.emplace_back(logs[i]);
    PagePipeserver p;
    p.index = static_cast<int>(i);
    p.place = i < places.size() ? places[i] : std::string();
    state_.pipeservers.push_back(std::move(p));
  }
}

bool LivePage::due() const {
  return publish_now_ || RunClock::now() - last_publish_ >= kPublishEvery;
}

bool LivePage::watched() const {
  return server_->watched(kWatchedWithin);
}

void LivePage::read_logs() {
  for (std::size_t i = 0; i < logs_.size(); ++i) {
    PagePipeserver& p = state_.pipeservers[i];
    logs_[i].read_new([&](const PipeserverLogLine& line) { take_log_line(p, line); });
  }
}

// The summary's "limited by ..." line, of the recent frames only.
std::string LivePage::limited_by(const PageMoment& m) const {
  RunTimes t;
  for (const PagePipeserver& p : state_.pipeservers) {
    t.render.emplace_back();
    for (const PageFrameTimes& f : p.recent) t.render.back().push_back(f.render_ms);
  }
  t.route = m.recent_route;
  t.refresh_hz = m.refresh_hz;
  const std::string lines = spread_lines(t);
  const auto at = lines.find("limited by ");
  if (at == std::string::npos) return {};
  return lines.substr(at, lines.find('\n', at) - at);
}

void LivePage::publish(const PageMoment& m, const DisplayPictures* pictures) {
  read_logs();
  state_.frame = m.frame;
  state_.fps = m.fps;
  state_.latency_frames = m.latency_frames;
  state_.paused = m.paused;
  state_.tiles = m.tiles;
  for (std::size_t i = 0; i < m.lost.size() && i < state_.pipeservers.size(); ++i)
    state_.pipeservers[i].lost = m.lost[i];
  state_.limited_by = limited_by(m);
  state_.balance_mode = m.balance_mode;
  state_.windows = m.windows;
  state_.windows_movable = m.windows_movable;
  state_.share_slots = m.share_slots;
  state_.shares = server_->shares()->shares(ShareInbox::Clock::now());
  state_.balance_modes.clear();
  if (!m.balance_mode.empty()) state_.balance_modes = {"static", "strips", "kd"};
  if (pictures) {
    auto shown = std::make_shared<std::vector<RgbImage>>();
    // As they hang, so the page draws a portrait panel upright (image/turn.hpp).
    for (const PageDisplay& d : state_.displays)
      shown->push_back(to_canvas((*pictures)(d.id), d.orientation));
    server_->publish_displays(std::move(shown));
    ++state_.pictures_version;
  }
  server_->publish(state_);
  last_publish_ = RunClock::now();
  publish_now_ = false;
}

void LivePage::event(int frame, std::string text) {
  state_.events.push_back({frame, std::move(text)});
  keep_last(state_.events, kEventsKept);
  publish_now_ = true;
}

std::vector<ControlRequest> LivePage::requests() {
  std::vector<ControlRequest> r = server_->inbox().take();
  if (!r.empty()) publish_now_ = true;
  return r;
}

void LivePage::decide(int frame, const ControlRequest& request, ControlDecision decision) {
  event(frame, decision.text);
  server_->inbox().decide(request.ticket, std::move(decision));
}

void LivePage::end(const std::string& how, const std::string& summary) {
  server_->refuse_steering("the run is over: " + how);
  read_logs();
  state_.ended = how;
  state_.summary = summary;
  state_.paused = false;
  server_->publish(state_);
  server_->let_readers_see_the_end(milliseconds(3000), milliseconds(2000));
}

}  // namespace l2
