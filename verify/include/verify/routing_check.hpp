// Checks a routing pixel by pixel: every tile pixel of the routing test pattern
// (tilelayout/test_pattern.hpp) carries the display position it belongs to, so from the wall's
// plan and the scanned-out frames alone (a pipeserver's captures, tilelayout --scanout, any
// program drawing headers per the spec) it can be said of every display pixel whether it is
// right, missing, misplaced (and by which strip, from where to where) or written twice, and
// of every strip pixel whether it fell behind a mullion. Pure logic: no files, no terminal.
//
// The strips are taken as the router takes them (spec §3, §5): every scanline of every input
// parsed header by header; inputs in ascending order, each top to bottom and left to right, a
// later strip overwriting an earlier one (the higher input on the bus wins), KEY and DEPTH
// strips composited as spec §7 says. The test pattern of compositing tiles
// (tilelayout/test_pattern.hpp) makes their composite the plain pattern, so a depth or keyed
// wall verifies like any other; only COPY pixels written twice count as written twice, since
// KEY and DEPTH strips are meant to cover others.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// What one display pixel turned out to be.
enum class PixelKind : std::uint8_t {
  Unplanned,  // no strip wrote it and the wall covers it with no tile: as it should be
  Right,      // shows the test pattern of its own position, written once by COPY
  Missing,    // no strip wrote it, though a tile of the wall covers it
  Misplaced,  // shows the pattern of another position (or display), or no pattern at all
  Twice,      // right in the end, but written by two or more strips
};

struct DisplayPoint {
  int display = 0, x = 0, y = 0;
  friend bool operator==(const DisplayPoint&, const DisplayPoint&) = default;
};

// Consecutive misplaced pixels of one strip on one display row, joined with those of the
// strips on the following source rows that land on the following display rows the same way (a
// tile with one wrong header field is one run).
struct MisplacedRun {
  int input = 0;
  int source_row = 0, source_x = 0;  // the run's first pixel in its frame (first row)
  std::uint64_t header = 0;          // the 48-bit header of the first row's strip
  DisplayPoint landed;               // where the run's first pixel was written
  int width = 0, rows = 1;
  std::optional<DisplayPoint> belongs;  // where its first pixel belongs; none: no test pattern
};

// Strip pixels a COPY header sends past its display's right or bottom edge: canvas this display
// does not show (a mullion, or the neighbour display's area). Display coordinates, x >= width
// or y >= height.
struct MullionRun {
  DisplayPoint start;
  int width = 0;
};

struct DisplayCheck {
  int display = 0, width = 0, height = 0;
  long long planned = 0;  // pixels the wall's tiles cover
  long long right = 0;    // showing their own position's pattern (Right and Twice)
  long long missing = 0, misplaced = 0;
  long long written_twice = 0;    // pixels two or more strips wrote, right or misplaced
  long long behind_mullions = 0;  // strip pixels past the display's edges (MullionRun)
  std::vector<PixelKind> kinds;   // width x height, row-major
  bool clean() const { return missing + misplaced + written_twice + behind_mullions == 0; }
};

// Where the parser refused a strip (spec §3): the scanline and the column of the header it
// could not take, and why ("check-bit error", ...).
struct RefusedAt {
  int row = 0, column = 0;
  const char* why = "";
};

// A strip that is not where or what the plan of its input's pipeserver says (spec §4): found
// (none: a planned strip that is not there) against planned (none: a strip the plan does not
// have at that place).
struct StripDifference {
  int row = 0, column = 0;  // of the strip's first colour pixel in the frame
  std::optional<StripHeader> found, planned;
};

// Frame parity of a frame's strips (spec §6): 0 or 1, or one of these.
inline constexpr int kNoParity = -1;    // no strip at all
inline constexpr int kMixedParity = 2;  // rows of both parities: a torn frame

struct InputCheck {
  int input = 0;
  long long copy_strips = 0;
  long long composited_strips = 0;  // KEY and DEPTH (spec §7)
  StripErrorCounts errors;          // the parser's (§3); its missing_display and clips stay 0
  long long to_absent_display = 0;  // COPY pixels for a display the wall does not have
  std::vector<RefusedAt> refused;   // the first few of `errors`, by place
  int width = 0, height = 0;        // the frame as given
  int planned_width = 0, planned_height = 0;  // its pipeserver's framebuffer; 0: none planned
  int parity = kNoParity;
  // Against the plan of pipeserver `input`: strips found where it has none or other than it
  // says, plus planned strips not found; the first of them; and, when the frame carries exactly
  // the strips planned for another pipeserver (a crossed cable), that pipeserver.
  long long not_as_planned = 0;
  std::optional<StripDifference> first_difference;
  std::optional<int> carries;
  bool refused_strips() const { return errors.total() != 0 || to_absent_display != 0; }
  bool size_differs() const {
    return planned_width != 0 && (width != planned_width || height != planned_height);
  }
  bool as_planned() const { return not_as_planned == 0 && !size_differs(); }
  bool clean() const { return !refused_strips() && as_planned() && parity != kMixedParity; }
};

struct RoutingCheck {
  int planned_inputs = 0;               // pipeservers in the wall's plan
  bool parity_differs = false;          // inputs whose strips carry different frame parities
  std::vector<DisplayCheck> displays;   // in wall order
  std::vector<InputCheck> inputs;       // one per frame given
  std::vector<MisplacedRun> misplaced;  // display by display, top to bottom, left to right
  std::vector<MullionRun> mullion_runs;
  bool clean() const;
};

// `frames[i]` is input i's scanned-out frame. `routed`, when given, holds per display (wall
// order) what a router made of the frames (nullptr or missing entries: not given): the pixel
// values are then read from it, so a router that copies other pixels than the headers say is
// caught too; otherwise from the frames.
RoutingCheck check_routing(const TileLayout& layout, std::span<const RgbImage> frames,
                           std::span<const RgbImage* const> routed = {});

}  // namespace l2
