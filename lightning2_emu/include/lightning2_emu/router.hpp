// The hot path of the emulator: reads scanned-out input frames scanline by scanline (spec §3)
// and copies their COPY strips into the back buffers of the displays it owns, with the overlap
// priority and background of spec §5.
//
// A frame is routed in three steps, so the frame sequencer (§6) can decide between them which
// inputs count:
//   scan()   parses every input in parallel into per-input lists of runs (headers only: the
//            pixels are not touched). A run is a tile's strips within one band of display rows:
//            the same source columns on consecutive scanlines going to consecutive rows;
//   write()  copies the runs of the chosen inputs into the back buffers, in parallel over
//            display row bands, inputs in ascending order so the higher input wins, and
//            records one rectangle per run;
//   finish() fills every pixel no strip wrote with the background and counts coverage and
//            overdraw from the rectangles, and starts the displays' next frame.
// Buffers are reused from frame to frame: after the first frames nothing is allocated. The
// result does not depend on the number of workers.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lightning2_emu/band_coverage.hpp"
#include "lightning2_emu/display_buffers.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "lightning2_emu/mesh.hpp"
#include "lightning2_emu/route_report.hpp"
#include "lightning2_emu/worker_pool.hpp"

namespace l2 {

class Router {
 public:
  // Throws MeshError for a display the mesh does not have, a repeated id or a bad size.
  Router(const Mesh& mesh, std::vector<DisplaySpec> displays, WorkerPool& pool,
         Rgb background = {});

  const Mesh& mesh() const { return mesh_; }
  int display_count() const { return static_cast<int>(displays_.size()); }
  DisplayBuffers& display(int index) { return displays_[index]; }
  const DisplayBuffers& display(int index) const { return displays_[index]; }
  int index_of_display(int id) const;  // -1 when the mesh has no display `id`
  Rgb background() const { return background_; }

  // Parses frames[i] as input i (a frame that is not present() counts as no signal).
  // Throws MeshError before parsing anything when there are more frames than mesh inputs or a
  // frame is larger than the board limit or has fewer than 3 bytes per pixel.
  void scan(std::span<const InputFrame> frames);
  const InputFrameStats& scanned(int input) const { return inputs_[input].stats; }

  // Writes the strips found by the last scan() for every input i with route_input[i] != 0.
  // The frames given to scan() must still be valid.
  void write(std::span<const std::uint8_t> route_input);

  // Completes the current frame of the displays with the given indices (not ids).
  void finish(std::span<const int> display_indices, std::vector<DisplayFrameStats>& out);

  // scan + write every input + finish every display: one whole frame, as `route` does.
  RouteReport route(std::span<const InputFrame> frames);

 private:
  // Where the strips of one display id go: the one table the scan looks up per strip.
  struct Target {
    int index = -1;  // display index; -1 when the mesh has no display with this id configured
    int width = 0, height = 0;
    int band_shift = 0;   // a strip of row y lies in band y >> band_shift of the display
    int band_offset = 0;  // its first band among all displays' bands
  };
  // COPY strips of one input, after clipping, that continue each other: the same source
  // columns on consecutive scanlines going to the same display columns on consecutive rows of
  // one band (a tile, or its part in the band). Strip k of the run is read from
  // src + k * stride and written to row dst_y + k.
  struct Run {
    std::int64_t src;  // byte offset of the first strip's first pixel from the frame's row 0
    std::int32_t src_x;
    std::int32_t row_lag;  // source row minus display row, the same for every strip of the run
    std::uint16_t dst_x, dst_y, length, rows;
  };
  // A run extended on the last scanline scanned: the next scanline's strip at the same source
  // column may continue it.
  struct OpenRun {
    std::int32_t src_x;
    std::uint32_t run;       // index in its band list
    std::uint64_t next_key;  // run_key() of the strip that would continue it
  };
  // Each worker appends to its own input's lists: cache-line alignment keeps neighbours, worked
  // on by other workers, off the same line.
  struct alignas(64) InputState {
    InputFrame frame;
    InputFrameStats stats;
    std::vector<std::vector<Run>> bands;  // [Target::band_offset + band], in write order
    std::vector<OpenRun> open, opening;   // by source column: last scanline's, this one's
  };
  // A band of display rows: one task's share. One area per run written (appending is all the
  // copy does); coverage is worked out from them when the frame is finished.
  struct alignas(64) BandState {
    std::vector<Area> areas;  // in write order
    std::uint64_t strips = 0;
    struct Written {  // a strip's columns written by an input, for the guard path
      std::uint16_t x0, x1, input;
    };
    std::vector<Written> by_row;           // earlier calls' areas, row by row (scratch)
    std::vector<std::uint32_t> row_start;  // by_row index of each row of the band, + end
  };
  struct DisplayState {
    int band_rows = 1, band_count = 1;
    int highest_input_written = -1;  // over earlier write() calls of this frame
    std::vector<BandState> bands;
  };
  struct BandTask {
    int display, band;
  };

  void scan_input(int input);
  static void group_by_row(BandState& band, int first_row, int rows);
  static void copy_visible(std::uint8_t* dst, const std::uint8_t* src, int x0, int x1, int bpp,
                           int input, const BandState& band, int band_row);
  void write_band(int display, int band, std::span<const std::uint8_t> route_input);
  DisplayFrameStats finish_band(int display, int band, CoverageScratch& scratch);

  Mesh mesh_;
  WorkerPool& pool_;
  Rgb background_;
  std::vector<DisplayBuffers> displays_;
  std::vector<DisplayState> display_state_;
  std::vector<Target> targets_;  // by display id: kMaxDisplays entries
  std::vector<InputState> inputs_;
  std::vector<BandTask> band_tasks_;
  std::vector<BandTask> finish_tasks_;
  std::vector<DisplayFrameStats> band_stats_;
  std::vector<int> scan_inputs_;
  struct alignas(64) WorkerScratch {
    CoverageScratch coverage;
  };
  std::vector<WorkerScratch> scratch_;  // one per worker
};

}  // namespace l2
