#include "plan_match.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace l2::verify_detail {
namespace {

// A strip by its place in the frame, and what its header says (parity aside: it changes every
// frame and has a check of its own).
struct Place {
  int row = 0, column = 0;
  auto operator<=>(const Place&) const = default;
};
struct Fields {
  int display = 0, x = 0, y = 0, width = 0;
  bool operator==(const Fields&) const = default;
};
using Strips = std::map<Place, Fields>;

Strips planned(const PipeserverPlan& plan) {
  Strips out;
  for (const PackedTile& p : plan.tiles) {
    const Rect& r = p.tile.on_display;
    for (int j = 0; j < r.h; ++j) out[{p.fb_y + j, p.fb_x}] = {p.tile.display, r.x, r.y + j, r.w};
  }
  return out;
}

Strips found(std::span<const FoundStrip> strips, int input) {
  Strips out;
  for (const FoundStrip& s : strips) {
    if (s.input != input) continue;
    out[{s.source_row, s.source_x}] = {s.header.display, s.header.x, s.header.y, s.header.width};
  }
  return out;
}

// Where a found strip's header starts and the next one's would.
struct Piece {
  int header_x, next_x;
  const FoundStrip* strip;
};

Piece piece_of(const FoundStrip& s) {
  const bool depth = s.how == Compositing::Depth;
  const bool ext = s.header.op == StripOp::Ext;
  return {s.source_x - kHeaderPixels - (ext ? 2 : 0), s.source_x + s.header.width * (depth ? 2 : 1),
          &s};
}

// Whether `pieces` (one scanline's, by header column) chain exactly over a DEPTH tile's gap and
// payload columns as a sparse row does: from its gap to the end of its depth pixels, each
// header where the last strip ends, every routed one a DEPTH strip inside the tile's display
// row.
bool sparse_row(const std::vector<Piece>& pieces, const PackedTile& p, int r) {
  const Rect& d = p.tile.on_display;
  int at = p.fb_x - gap_columns(p.tile);
  const int end = p.fb_x + payload_columns(p.tile);
  for (const Piece& piece : pieces) {
    if (piece.header_x < at) continue;
    if (at == end) break;
    if (piece.header_x != at) return false;
    const StripHeader& h = piece.strip->header;
    if (h.op != StripOp::Skip &&
        (piece.strip->how != Compositing::Depth || h.display != p.tile.display || h.y != d.y + r ||
         h.x < d.x || h.x + h.width > d.x + d.w)) {
      return false;
    }
    at = piece.next_x;
  }
  return at == end;
}

// The strips found on the input, with each sparse DEPTH row of `plan` taken as its planned strip.
Strips found_for(const PipeserverPlan& plan, std::span<const FoundStrip> strips,
                 std::span<const FoundStrip> skips, int input) {
  Strips out = found(strips, input);
  std::map<int, std::vector<Piece>> rows;
  for (auto list : {strips, skips}) {
    for (const FoundStrip& s : list) {
      if (s.input == input) rows[s.source_row].push_back(piece_of(s));
    }
  }
  for (auto& [row, pieces] : rows) {
    std::sort(pieces.begin(), pieces.end(),
              [](const Piece& a, const Piece& b) { return a.header_x < b.header_x; });
  }
  for (const PackedTile& p : plan.tiles) {
    if (p.tile.compositing != Compositing::Depth) continue;
    const Rect& d = p.tile.on_display;
    for (int r = 0; r < d.h; ++r) {
      const auto it = rows.find(p.fb_y + r);
      if (it == rows.end() || !sparse_row(it->second, p, r)) continue;
      for (const Piece& piece : it->second) {
        if (piece.strip->header.op != StripOp::Skip &&
            piece.header_x >= p.fb_x - gap_columns(p.tile) &&
            piece.header_x < p.fb_x + payload_columns(p.tile)) {
          out.erase({p.fb_y + r, piece.strip->source_x});
        }
      }
      out[{p.fb_y + r, p.fb_x}] = {p.tile.display, d.x, d.y + r, d.w};
    }
  }
  return out;
}

StripHeader header_of(const Fields& f) {
  return StripHeader::copy(false, f.display, f.x, f.y, f.width);
}

// How many strips differ between the two, and the first (by row, then column).
long long compare(const Strips& got, const Strips& plan, std::optional<StripDifference>& first) {
  long long differ = 0;
  const auto note = [&](const Place& at, const Fields* g, const Fields* p) {
    ++differ;
    if (first && std::tie(first->row, first->column) <= std::tie(at.row, at.column)) return;
    first = StripDifference{at.row, at.column, g ? std::optional(header_of(*g)) : std::nullopt,
                            p ? std::optional(header_of(*p)) : std::nullopt};
  };
  for (const auto& [at, fields] : got) {
    const auto it = plan.find(at);
    if (it == plan.end() || !(it->second == fields))
      note(at, &fields, it == plan.end() ? nullptr : &it->second);
  }
  for (const auto& [at, fields] : plan) {
    if (!got.contains(at)) note(at, nullptr, &fields);
  }
  return differ;
}

}  // namespace

void match_plans(const TileLayout& layout, std::span<const FoundStrip> strips,
                 std::span<const FoundStrip> skips, std::vector<InputCheck>& inputs) {
  std::vector<Strips> plans;
  for (const PipeserverPlan& p : layout.pipeservers) plans.push_back(planned(p));
  for (InputCheck& input : inputs) {
    const auto i = static_cast<std::size_t>(input.input);
    const Strips got = i < layout.pipeservers.size()
                           ? found_for(layout.pipeservers[i], strips, skips, input.input)
                           : found(strips, input.input);
    if (i < layout.pipeservers.size()) {
      input.planned_width = layout.pipeservers[i].fb_width;
      input.planned_height = layout.pipeservers[i].fb_height;
    }
    input.not_as_planned =
        compare(got, i < plans.size() ? plans[i] : Strips{}, input.first_difference);
    if (input.not_as_planned == 0 || got.empty()) continue;
    for (std::size_t j = 0; j < plans.size(); ++j) {
      if (j != i && found_for(layout.pipeservers[j], strips, skips, input.input) == plans[j])
        input.carries = static_cast<int>(j);
    }
  }
}

}  // namespace l2::verify_detail
