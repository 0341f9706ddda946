#include <nlohmann/json.hpp>

#include "control_page/run_state.hpp"

namespace l2 {
namespace {

using nlohmann::json;

json rect(int x, int y, int width, int height) {
  return {{"x", x}, {"y", y}, {"width", width}, {"height", height}};
}

json displays(const std::vector<PageDisplay>& all) {
  json out = json::array();
  for (const PageDisplay& d : all) {
    json j = rect(d.x, d.y, d.width, d.height);
    j["id"] = d.id;
    j["swap_group"] = d.swap_group;
    j["rotation"] = d.orientation.rotation;
    j["flip"] = kFlipNames[static_cast<int>(d.orientation.flip)];
    out.push_back(j);
  }
  return out;
}

json tiles(const std::vector<PageTile>& all) {
  json out = json::array();
  for (const PageTile& t : all) {
    json j = rect(t.x, t.y, t.width, t.height);
    j["pipeserver"] = t.pipeserver;
    out.push_back(j);
  }
  return out;
}

json windows(const std::vector<PageWindow>& all) {
  json out = json::array();
  for (const PageWindow& w : all) {
    json j = rect(w.x, w.y, w.width, w.height);
    j["id"] = w.id;
    j["source"] = w.source;
    out.push_back(j);
  }
  return out;
}

json shares(const std::vector<PageShare>& all) {
  json out = json::array();
  for (const PageShare& s : all) {
    out.push_back({{"window", s.window},
                   {"name", s.name},
                   {"width", s.width},
                   {"height", s.height},
                   {"received", s.received},
                   {"shown", s.shown},
                   {"dropped", s.dropped},
                   {"refused", s.refused},
                   {"seconds_since_frame", s.seconds_since_frame}});
  }
  return out;
}

json pipeservers(const std::vector<PagePipeserver>& all) {
  json out = json::array();
  for (const PagePipeserver& p : all) {
    json recent = json::array();
    for (const PageFrameTimes& f : p.recent) {
      recent.push_back({{"frame", f.frame},
                        {"render_ms", f.render_ms},
                        {"ready_wait_ms", f.ready_wait_ms},
                        {"sync_retries", f.sync_retries}});
    }
    out.push_back({{"index", p.index},
                   {"place", p.place},
                   {"recent", recent},
                   {"back_channel", p.back_channel},
                   {"renderer", p.renderer},
                   {"lost", p.lost}});
  }
  return out;
}

json events(const std::vector<PageEvent>& all) {
  json out = json::array();
  for (const PageEvent& e : all) out.push_back({{"frame", e.frame}, {"text", e.text}});
  return out;
}

}  // namespace

std::string to_json(const RunState& s) {
  const json j = {
      {"wall", {{"name", s.wall_name}, {"canvas", rect(0, 0, s.canvas_width, s.canvas_height)}}},
      {"displays", displays(s.displays)},
      {"path", s.path},
      {"frames_planned", s.frames_planned},
      {"frame", s.frame},
      {"fps", s.fps},
      {"latency_frames", s.latency_frames},
      {"limited_by", s.limited_by},
      {"paused", s.paused},
      {"stoppable", s.stoppable},
      {"live", s.live},
      {"ended", s.ended},
      {"summary", s.summary},
      {"balance", {{"mode", s.balance_mode}, {"modes", s.balance_modes}}},
      {"tiles", tiles(s.tiles)},
      {"windows", {{"shown", windows(s.windows)}, {"movable", s.windows_movable}}},
      {"shares", {{"slots", s.share_slots}, {"shown", shares(s.shares)}}},
      {"pipeservers", pipeservers(s.pipeservers)},
      {"events", events(s.events)},
      {"pictures", s.pictures},
      {"pictures_version", s.pictures_version},
  };
  // Replaced, not thrown: a wall or file name is the user's text and need not be UTF-8.
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace l2
