// The router's working state, kept out of its public header: where strips go, the runs a scan
// finds, and what each band of display rows wrote.
#pragma once

#include <cstdint>
#include <vector>

#include "band_coverage.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "lightning2_emu/route_report.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2::router_detail {

// Where the strips of one display id go: the one table the scan looks up per strip.
struct Target {
  int index = -1;  // display index; -1 when the mesh has no display with this id configured
  int width = 0, height = 0;
  int band_shift = 0;   // a strip of row y lies in band y >> band_shift of the display
  int band_offset = 0;  // its first band among all displays' bands
};

// COPY strips of one input, after clipping, that continue each other: the same source columns
// on consecutive scanlines going to the same display columns on consecutive rows of one band (a
// tile, or its part in the band). Strip k of the run is read from src + k * stride and written
// to row dst_y + k.
struct Run {
  std::int64_t src;  // byte offset of the first strip's first pixel from the frame's row 0
  std::int32_t src_x;
  std::int32_t row_lag;  // source row minus display row, the same for every strip of the run
  std::uint16_t dst_x, dst_y, length, rows;
  // The first strip's header without check bits and with the frame bit cleared (the 45-bit
  // message): strip k's header is this with y + k, for checking a predicted frame.
  std::uint64_t message;
};

// A header the last parse read that starts no routed strip (a SKIP, an END, a COPY in the last
// two pixels), for checking a predicted frame: at `at` bytes from row 0, `message` as in Run,
// or kAnyEnd when any END header will do (the parser reads nothing else of an END).
struct KeptHeader {
  std::int64_t at;
  std::uint64_t message;
  static constexpr std::uint64_t kAnyEnd = ~std::uint64_t{0};
};

// A header of the last scanline scanned, as the next scanline would repeat it.
struct SeenHeader {
  std::int32_t x;       // its column
  std::uint64_t value;  // the raw 48 bits that repeat it one scanline down: a COPY's row plus one
  std::int32_t list;    // a routed COPY: the band list of its run; otherwise -1
  std::uint32_t run;    // the run's index in that list
  std::int32_t next_y;  // a routed COPY: the display row a repeat writes ...
  std::int32_t last_y;  // ... which must not pass this one (display height, end of the band)
};

// One input's frame and what scanning it found. Each worker appends to its own input's lists:
// cache-line alignment keeps neighbours, worked on by other workers, off the same line.
//
// A frame's runs and headers are kept for the next frame: when the last frame parsed without
// error or tear, the next one is predicted to hold the same headers with the frame bit of its
// first strip (read, the only header read before the write). write() checks every header of a
// predicted frame: in the copy loop where it reads the strip after it anyway, the rest in a
// pass of their own.
struct alignas(64) InputScan {
  InputFrame frame;
  InputFrameStats stats;
  std::vector<std::vector<Run>> bands;   // [Target::band_offset + band], in write order
  std::vector<SeenHeader> seen, seeing;  // the last scanline's headers, this one's
  std::vector<KeptHeader> others;        // headers that start no routed strip, in scan order
  bool layout_kept = false;              // the last parse was clean: the next can be predicted
  InputFrame kept_shape;                 // the last parsed frame (its size, stride, pixel size)
  std::int64_t parity_at = -1;           // the first COPY/SKIP header, -1 when none
  bool predicted = false;                // stats and runs are a prediction not yet checked
  int parity = 0;                        // a predicted frame's parity
};

// Parses in.frame (present, checked against the mesh) into in.bands and in.stats, and keeps
// what the next frame's prediction needs.
void scan_input(InputScan& in, int input, const std::vector<Target>& targets);

// Predicts in.frame from the last parse if that was kept and the frame has the same shape;
// false when it must be parsed instead.
bool predict_input(InputScan& in);

// Checks a predicted frame's headers that write() does not: `others` always, the runs' too
// when `runs` (the input is not written, or is written after others this frame).
bool check_predicted(const InputScan& in, bool runs);

// Whether some run's rectangle shares a pixel with some area's.
bool any_overlap(const std::vector<Run>& runs, const std::vector<Area>& areas);

// The raw header a predicted strip must hold, from its message (frame bit included).
inline std::uint64_t predicted_header(std::uint64_t message) {
  return message << 3 | crc3(message);
}
inline constexpr std::uint64_t kMessageFrameBit = std::uint64_t{1}
                                                  << (header_bits::kFrameShift - 3);
inline constexpr std::uint64_t kMessageOneRow = std::uint64_t{1} << (header_bits::kYShift - 3);

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
  int highest_input_written = -1;  // over earlier write() calls of this frame
  std::vector<BandState> bands;
};

// A worker's scratch, reused from frame to frame.
struct alignas(64) WorkerScratch {
  CoverageScratch coverage;
};

}  // namespace l2::router_detail
