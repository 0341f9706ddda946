// The router's working state, kept out of its public header: where strips go, the runs a scan
// finds, and what each band of display rows wrote.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "image/band_coverage.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "lightning2_emu/route_report.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2::router_detail {

using coverage::Area;
using coverage::CoverageCounts;
using coverage::CoverageScratch;
using coverage::sweep_coverage;

// Where the strips of one display id go: the one table the scan looks up per strip.
struct Target {
  int index = -1;  // display index; -1 when the mesh has no display with this id configured
  int width = 0, height = 0;
  int band_shift = 0;   // a strip of row y lies in band y >> band_shift of the display
  int band_offset = 0;  // its first band among all displays' bands
};

// What a run's strips do to their display pixels (spec §7).
enum class StripKind : std::uint8_t { Copy, Key, Depth };

// COPY, KEY or DEPTH strips of one input, after clipping, that continue each other: the same source
// columns on consecutive scanlines going to the same display columns on consecutive rows of one
// band (a tile, or its part in the band). Strip k of the run is read from src + k * stride and
// written to row dst_y + k.
struct Run {
  std::int64_t src;  // byte offset of the first strip's first pixel from the frame's row 0
  std::int32_t src_x;
  std::int32_t row_lag;  // source row minus display row, the same for every strip of the run
  std::uint16_t dst_x, dst_y, length, rows;
  StripKind kind;
  std::uint16_t depth_at;  // DEPTH: depth pixel i is this many pixels after colour pixel i
  std::uint32_t key;       // KEY: the key colour, R<<16 | G<<8 | B
  std::uint64_t ext;       // KEY/DEPTH: the raw extension word, the same on every strip; else 0
  // The first strip's header without check bits and with the frame bit cleared (the 45-bit
  // message): strip k's header is this with y + k, for checking a predicted frame.
  std::uint64_t message;
};

// A header the last parse read that starts no routed strip (a SKIP, an END, a COPY in the last
// two pixels), for checking a predicted frame: at `at` bytes from row 0, `message` as in Run,
// or kAnyEnd when any END header will do (the parser reads nothing else of an END).
struct RememberedHeader {
  std::int64_t at;
  std::uint64_t message;
  static constexpr std::uint64_t kAnyEnd = ~std::uint64_t{0};
};

// A header of the last scanline scanned, as the next scanline would repeat it.
struct SeenHeader {
  std::int32_t x;         // its column
  std::uint64_t value;    // the raw 48 bits that repeat it one scanline down: a COPY's row plus one
  std::int32_t list;      // a routed COPY: the band list of its run; otherwise -1
  std::uint32_t run;      // the run's index in that list
  std::int32_t next_y;    // a routed COPY: the display row a repeat writes ...
  std::int32_t last_y;    // ... which must not pass this one (display height, end of the band)
  std::uint64_t ext = 0;  // a KEY/DEPTH: its raw extension word, which a repeat must hold too
  StripKind kind = StripKind::Copy;
};

// What parsing one frame leaves: the runs to write, the headers that start no run (remembered for
// checking a prediction) and the counts.
struct Layout {
  InputFrameStats stats;
  std::vector<std::vector<Run>> bands;   // [Target::band_offset + band], in write order
  std::vector<RememberedHeader> others;  // headers that start no routed strip, in scan order
  std::int64_t parity_at = -1;           // the first COPY/SKIP/EXT header, -1 when none
  std::uint64_t composited = 0;          // bit d: a KEY or DEPTH strip reached display d
};

// A parse's working lists, reused from frame to frame.
struct ScanScratch {
  std::vector<SeenHeader> seen, seeing;  // the last scanline's headers, this one's
};

// Parses `frame` (present, checked against the mesh) as input `input` into `out`.
void parse_frame(const InputFrame& frame, int input, const std::vector<Target>& targets,
                 Layout& out, ScanScratch& scratch);

// One input: its frame, and what the last parse of it left, from which the next frame is
// predicted (router.hpp). Each worker works on its own input: cache-line alignment keeps
// neighbours, worked on by other workers, off the same line.
//   None       nothing to predict from: no signal, no parse yet, or the last parse found an
//              error or a tear. The next frame is parsed.
//   Parsed     the frame was parsed clean, or its prediction held: the next frame of the same
//              size, stride and pixel size is predicted.
//   Predicted  the frame is taken to hold the last parse's headers with the frame bit of its
//              first routing header (the one header read), and its counts; every header is
//              checked before the frame counts (write(): in the copy, and headers_hold()).
class alignas(64) InputScan {
 public:
  enum class State : std::uint8_t { None, Parsed, Predicted };

  void init(int input, int band_lists);
  // No signal this refresh: nothing to route, nothing to predict the next frame from.
  void no_signal();
  void parse(const InputFrame& frame, const std::vector<Target>& targets);
  // Predicts `frame` from the last parse; false, changing nothing, when it must be parsed.
  bool predict(const InputFrame& frame);
  // Whether a predicted frame's headers hold that write() does not check in the copy: the last
  // parse's ones always, the runs' too when `runs` (not copied, or not checked while copied).
  bool headers_hold(bool runs) const;
  // Every check held: the prediction is the frame's parse.
  void verified() { state_ = State::Parsed; }
  // One did not: the frame is parsed after all.
  void reparse(const std::vector<Target>& targets) { parse(frame_, targets); }

  State state() const { return state_; }
  bool predicted() const { return state_ == State::Predicted; }
  const InputFrame& frame() const { return frame_; }
  const InputFrameStats& stats() const { return layout_.stats; }
  const std::vector<Run>& runs(int band_list) const { return layout_.bands[band_list]; }
  // Bit d: display d gets a KEY or DEPTH strip of this frame (its parse, or the prediction's).
  std::uint64_t composited() const { return layout_.composited; }
  // The frame bit of a predicted frame's headers, in a header message (0 when not predicted).
  std::uint64_t frame_bit() const;

 private:
  InputFrame frame_;
  Layout layout_;
  ScanScratch scratch_;
  int input_ = 0;
  int parity_ = 0;  // a predicted frame's
  State state_ = State::None;
};

// Whether some run's rectangle shares a pixel with some area's.
bool any_overlap(const std::vector<Run>& runs, const std::vector<Area>& areas);

// The raw header a predicted strip must hold, from its message (frame bit included).
inline std::uint64_t predicted_header(std::uint64_t message) {
  return message << 3 | crc3(message);
}
inline constexpr std::uint64_t kMessageFrameBit = std::uint64_t{1}
                                                  << (header_bits::kFrameShift - 3);
inline constexpr std::uint64_t kMessageOneRow = std::uint64_t{1} << (header_bits::kYShift - 3);

// The check bits of a header's y field alone, for every y: the CRC is linear in the message, so
// a header's check bits are those of its other fields XOR these.
struct YCheckBits {
  std::uint8_t of[4096]{};
  constexpr YCheckBits() {
    for (std::uint64_t y = 0; y < 4096; ++y) {
      of[y] = header_bits::remainder_bitwise(y << header_bits::kYShift);
    }
  }
};
inline constexpr YCheckBits kYCheckBits;

// The predicted headers of a run's strips: strip k's is the first's with y + k. One table load a
// strip instead of a CRC over all the header's bytes.
class RunHeaders {
 public:
  explicit RunHeaders(std::uint64_t message)
      : message_(message),
        rest_(message & ~kYField),
        rest_check_(crc3(message & ~kYField)),
        y0_(static_cast<int>(message >> kYAt & header_bits::k12Bits)) {}
  std::uint64_t strip(int k) const {
    const int y = y0_ + k;
    if (y > static_cast<int>(header_bits::k12Bits)) {  // y carries into x: no run does this
      return predicted_header(message_ + static_cast<std::uint64_t>(k) * kMessageOneRow);
    }
    return (rest_ | std::uint64_t(y) << kYAt) << 3 | (rest_check_ ^ kYCheckBits.of[y]);
  }

 private:
  static constexpr int kYAt = header_bits::kYShift - 3;  // the y field's place in a message
  static constexpr std::uint64_t kYField = header_bits::k12Bits << kYAt;
  std::uint64_t message_, rest_;
  std::uint8_t rest_check_;
  int y0_;
};

// The raw header in the two pixels before `pixels`, which hold at least one pixel of the
// strip: with RGB pixels the header's six bytes and the next two are one load.
inline std::uint64_t header_before(const std::uint8_t* pixels, int bpp) {
  const std::uint8_t* h = pixels - kHeaderPixels * bpp;
  if (bpp != 3) return header_value(h, h + bpp);
  std::uint64_t v;
  std::memcpy(&v, h, sizeof v);
  if constexpr (std::endian::native == std::endian::little) v = __builtin_bswap64(v);
  return v >> 16;
}

// A band of display rows: one task's share. One area per run written (appending is all the
// copy does); coverage, overdraw and the strip count are worked out from them when the frame
// is finished.
struct alignas(64) BandState {
  std::vector<Area> areas;  // in write order
  struct Written {          // columns of a row written by an input, for the guard path
    std::uint16_t x0, x1, input;
  };
  std::vector<Written> by_row;           // earlier calls' areas, row by row (scratch)
  std::vector<std::uint32_t> row_start;  // by_row index of each row of the band, + end
  std::vector<int> mispredicted;         // inputs whose strips here did not hold their headers
  // What earlier write() calls of this frame left (areas[0, earlier_areas)): a write() that
  // finds a prediction wrong goes back to it.
  std::size_t earlier_areas = 0;
};

struct DisplayBands {
  int band_rows = 1, band_count = 1;
  // Displays that get KEY or DEPTH strips: one value a pixel (composite.hpp), the whole display,
  // allocated the first time a parse finds such a strip for it. Empty for COPY-only displays.
  std::vector<std::uint32_t> plane;
  int highest_input_written = -1;  // over earlier write() calls of this frame
  std::vector<BandState> bands;
  // Displays with a plane: per row of each of the two buffers the router writes in turn (known
  // by its pixels' address, as the display's swaps exchange them), the columns that may hold
  // something other than the background: what the last frame routed into it reached. Outside
  // them the buffer holds the background already, and finishing a frame need not fill it
  // again. A buffer not seen yet is taken as reached everywhere.
  struct Reached {
    const std::uint8_t* buffer = nullptr;
    std::vector<int> x0, x1;
  };
  std::array<Reached, 2> reached;
  int reached_now = 0;  // the back buffer's, chosen by finish() before the bands run
};

// A worker's scratch, reused from frame to frame.
struct alignas(64) WorkerScratch {
  CoverageScratch coverage;
  std::vector<int> row_x0, row_x1;  // a band's rows: the columns its areas reach (finish_band)
};

}  // namespace l2::router_detail
