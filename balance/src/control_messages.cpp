#include "balance/control_messages.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "balance/message_words.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

// A canvas rectangle's four words; `what` names them in errors ("batch " + "width").
Rect take_rect(Words& w, const std::string& what) {
  Rect r;
  r.x = static_cast<int>(w.integer((what + "x").c_str(), 0, 65535));
  r.y = static_cast<int>(w.integer((what + "y").c_str(), 0, 65535));
  r.w = static_cast<int>(w.integer((what + "width").c_str(), 1, 65535));
  r.h = static_cast<int>(w.integer((what + "height").c_str(), 1, 65535));
  return r;
}

}  // namespace

std::string encode(const TimesMessage& m) {
  std::string out = fmt::format("TIMES {} {} {}", m.frame, m.pipeserver, m.seconds.size());
  for (double s : m.seconds) out += fmt::format(" {}", s);  // shortest exact form
  if (!m.footprints.empty()) {
    out += fmt::format(" BATCHES {}", m.footprints.size());
    for (const BatchFootprint& f : m.footprints) {
      const Rect& r = f.on_canvas;
      out += fmt::format(" {} {} {} {} {}", r.x, r.y, r.w, r.h, std::llround(f.triangles));
    }
  }
  return out;
}

std::string encode(const LayoutMessage& m) {
  std::string out = fmt::format("LAYOUT {} {}", m.frame, m.tiles.size());
  for (std::size_t i = 0; i < m.tiles.size(); ++i) {
    const Rect& r = m.tiles[i];
    out += fmt::format(" {} {} {} {} {}", r.x, r.y, r.w, r.h, m.pipeservers[i]);
  }
  if (!m.gone.empty()) {
    out += fmt::format(" GONE {}", m.gone.size());
    for (int s : m.gone) out += fmt::format(" {}", s);
  }
  return out;
}

TimesMessage decode_times(std::string_view line) {
  Words w(line);
  w.keyword("TIMES");
  TimesMessage m;
  m.frame = static_cast<int>(w.integer("frame", 0, kMaxFrame));
  m.pipeserver = static_cast<int>(w.integer("pipeserver", 0, kMaxPipeservers - 1));
  const auto n = w.integer("tile count", 0, kMaxControlTiles);
  for (long long i = 0; i < n; ++i) m.seconds.push_back(w.seconds());
  if (w.optional_keyword("BATCHES")) {
    const auto batches = w.integer("batch count", 1, kMaxControlBatches);
    for (long long i = 0; i < batches; ++i) {
      const Rect r = take_rect(w, "batch ");
      const auto triangles = w.integer("batch triangles", 0, 1LL << 40);
      m.footprints.push_back({r, double(triangles)});
    }
  }
  w.end();
  return m;
}

LayoutMessage decode_layout(std::string_view line) {
  Words w(line);
  w.keyword("LAYOUT");
  LayoutMessage m;
  m.frame = static_cast<int>(w.integer("frame", 0, kMaxFrame));
  const auto n = w.integer("tile count", 1, kMaxControlTiles);
  for (long long i = 0; i < n; ++i) {
    m.tiles.push_back(take_rect(w, ""));
    m.pipeservers.push_back(static_cast<int>(w.integer("pipeserver", 0, kMaxPipeservers - 1)));
  }
  if (w.optional_keyword("GONE")) {
    const auto gone = w.integer("gone count", 1, kMaxPipeservers);
    for (long long i = 0; i < gone; ++i) {
      m.gone.push_back(static_cast<int>(w.integer("gone pipeserver", 0, kMaxPipeservers - 1)));
      if (i > 0 && m.gone[i] <= m.gone[i - 1]) w.fail("gone pipeservers must be ascending");
    }
  }
  w.end();
  return m;
}

std::string encode(const WantMessage& m) {
  return fmt::format("WANT {} {}", m.frame, m.pipeserver);
}

std::string encode(const WindowsMessage& m) {
  std::string out = fmt::format("WINDOWS {} {}", m.frame, m.windows.size());
  for (const WindowPlace& w : m.windows) {
    const Rect& r = w.on_canvas;
    out += fmt::format(" {} {} {} {} {}", w.id, r.x, r.y, r.w, r.h);
  }
  return out;
}

WantMessage decode_want(std::string_view line) {
  Words w(line);
  w.keyword("WANT");
  WantMessage m;
  m.frame = static_cast<int>(w.integer("frame", 0, kMaxFrame));
  m.pipeserver = static_cast<int>(w.integer("pipeserver", 0, kMaxPipeservers - 1));
  w.end();
  return m;
}

WindowsMessage decode_windows(std::string_view line) {
  Words w(line);
  w.keyword("WINDOWS");
  WindowsMessage m;
  m.frame = static_cast<int>(w.integer("frame", 0, kMaxFrame));
  const auto n = w.integer("window count", 0, kMaxControlWindows);
  for (long long i = 0; i < n; ++i) {
    WindowPlace p;
    p.id = static_cast<int>(w.integer("window id", 0, kMaxControlWindowId));
    p.on_canvas.x = static_cast<int>(w.integer("x", -kControlWindowReach, kControlWindowReach));
    p.on_canvas.y = static_cast<int>(w.integer("y", -kControlWindowReach, kControlWindowReach));
    p.on_canvas.w = static_cast<int>(w.integer("width", 1, kMaxControlWindowSide));
    p.on_canvas.h = static_cast<int>(w.integer("height", 1, kMaxControlWindowSide));
    for (const WindowPlace& before : m.windows)
      if (before.id == p.id) w.fail(fmt::format("window {} listed twice", p.id));
    m.windows.push_back(p);
  }
  w.end();
  return m;
}

LayoutMessage layout_message(int frame, const TileLayout& layout) {
  LayoutMessage m;
  m.frame = frame;
  m.tiles = layout.logical_tiles;
  m.pipeservers.assign(layout.logical_tiles.size(), 0);
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    m.pipeservers[static_cast<std::size_t>(layout.tiles[i].logical_tile)] =
        layout.tile_pipeserver[i];
  }
  for (const PipeserverPlan& s : layout.pipeservers) {
    if (s.tiles.empty()) m.gone.push_back(s.pipeserver);
  }
  return m;
}

TileLayout plan_from_message(const Wall& wall, const LayoutMessage& m) {
  Wall w = wall;
  w.tiling = {};
  w.tiling.kind = TilingKind::List;
  w.tiling.rects = m.tiles;
  return m.gone.empty() ? plan_layout(w, m.pipeservers) : plan_layout(w, m.pipeservers, m.gone);
}

}  // namespace l2
