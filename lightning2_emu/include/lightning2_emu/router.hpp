// The hot path of the emulator: reads scanned-out input frames scanline by scanline (spec §3)
// and copies their COPY strips into the back buffers of the displays it owns, with the overlap
// priority and background of spec §5.
//
// A frame is routed in three steps, so the frame sequencer (§6) can decide between them which
// inputs count:
//   scan()   parses every input in parallel into per-input lists of runs (headers only: the
//            pixels are not touched). A run is a tile's strips within one band of display rows:
//            the same source columns on consecutive scanlines going to consecutive rows;
//   write()  asks the caller which inputs to route, from the counts of the scan, and copies
//            the runs of those into the back buffers, in parallel over display row bands,
//            inputs in ascending order so the higher input wins, recording one rectangle per
//            run;
//   finish() fills every pixel no strip wrote with the background and counts coverage and
//            overdraw from the rectangles, and starts the displays' next frame.
// Buffers are reused from frame to frame: after the first frames nothing is allocated. The
// result does not depend on the number of workers.
//
// Frames that repeat their input's layout are predicted, not parsed. A pipeserver draws the
// same headers frame after frame, only the frame bit alternates, so after a frame without
// error or tear scan() predicts the next one holds the same headers with the frame bit of
// its first strip (the one header it reads), and gives the last frame's counts. write() then
// checks every header of the prediction: a strip's header in the copy loop, which reads that
// line anyway, the others in a pass of their own. When one differs, write() undoes what it
// wrote, parses the input, asks the caller's choice again on the parsed counts and writes
// that. So the result is that of a parse, header for header, count for count, and nothing
// outside the router sees a prediction; it saves the parse's pass over the frame.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "lightning2_emu/display_buffers.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "lightning2_emu/mesh.hpp"
#include "lightning2_emu/route_report.hpp"
#include "lightning2_emu/worker_pool.hpp"

namespace l2 {

namespace router_detail {  // src/router_detail.hpp
struct Target;
class InputScan;
struct DisplayBands;
struct WorkerScratch;
}  // namespace router_detail

class Router {
 public:
  // Throws MeshError for a display the mesh does not have, a repeated id or a bad size.
  Router(const Mesh& mesh, std::vector<DisplaySpec> displays, WorkerPool& pool,
         Rgb background = {});
  ~Router();

  const Mesh& mesh() const { return mesh_; }
  int display_count() const { return static_cast<int>(displays_.size()); }
  DisplayBuffers& display(int index) { return displays_[index]; }
  const DisplayBuffers& display(int index) const { return displays_[index]; }
  int index_of_display(int id) const;  // -1 when the mesh has no display `id`
  Rgb background() const { return background_; }
  // Whether display `index` has a compositing plane: it got KEY or DEPTH strips (spec §7).
  bool composites(int index) const;

  // Parses, or predicts (see above), frames[i] as input i (a frame that is not present()
  // counts as no signal). Throws MeshError before parsing anything when there are more frames
  // than mesh inputs or a frame is larger than the board limit or has fewer than 3 bytes per
  // pixel.
  void scan(std::span<const InputFrame> frames);
  // Input `input`'s counts from the last scan(): what write() chooses by, and the frame's
  // parse once write() has returned.
  const InputFrameStats& scanned(int input) const;

  // Which inputs to write (route[i] != 0: input i), chosen from scanned(). It may be asked
  // twice in one write(), the second time on counts a parse corrected, so it must choose from
  // scanned() alone and change nothing; the span must stay valid until write() returns.
  using RouteChoice = std::function<std::span<const std::uint8_t>()>;
  // Writes the strips found by the last scan() for the inputs `choose` picks. The frames given
  // to scan() must still be valid.
  void write(const RouteChoice& choose);
  // The same for a fixed choice.
  void write(std::span<const std::uint8_t> route_input);

  // On by default; off, every frame is parsed (to measure the parse, or compare the two).
  void predict_layouts(bool on) { predict_ = on; }

  // Frames predicted so far, and how many of those turned out different and were parsed.
  // `checked_first`: predictions checked before writing, because a strip of one overlapped
  // what an earlier write() call of the same frame had written.
  struct PredictionCounts {
    std::uint64_t predicted = 0, mispredicted = 0, checked_first = 0;
  };
  const PredictionCounts& predictions() const { return predictions_; }

  // Completes the current frame of the displays with the given indices (not ids).
  void finish(std::span<const int> display_indices, std::vector<DisplayFrameStats>& out);

  // scan + write every input + finish every display: one whole frame, as `route` does.
  RouteReport route(std::span<const InputFrame> frames);

 private:
  struct BandTask {
    int display, band;
  };

  // write() for one choice; false when a predicted frame turned out different, having
  // retained nothing of this call (pixels it wrote outside earlier calls' strips get the background
  // in finish() unless written again), the input parsed.
  bool write_checked(std::span<const std::uint8_t> route_input);
  void write_band(int band_list, std::span<const std::uint8_t> route_input);
  // Checks every predicted input's headers that the copy did not (all of them unless `copied`),
  // parses the inputs that differ; false when one did.
  bool confirm_predictions(std::span<const std::uint8_t> route_input, bool copied);
  // Whether no strip of a predicted input routed now overlaps an area an earlier write() call
  // of this frame wrote: then its headers can be checked in the copy (write()).
  bool predictions_clear_of_earlier(std::span<const std::uint8_t> route_input) const;
  // Which of the display's two buffers finish() writes into, for its background (finish_band).
  void choose_reached(int display);
  DisplayFrameStats finish_band(int display, int band, router_detail::WorkerScratch& scratch);
  // Gives every display the scan found KEY or DEPTH strips for its compositing plane, once.
  void add_planes();
  void composite_band(int task, std::span<const std::uint8_t> route_input);

  Mesh mesh_;
  WorkerPool& pool_;
  Rgb background_;
  std::vector<DisplayBuffers> displays_;
  std::vector<router_detail::DisplayBands> display_state_;
  std::vector<router_detail::Target> targets_;  // by display id: kMaxDisplays entries
  std::vector<router_detail::InputScan> inputs_;
  std::vector<BandTask> band_tasks_;  // [band list]: every band of every display
  std::vector<BandTask> finish_tasks_;
  std::vector<DisplayFrameStats> band_stats_;
  std::vector<int> scan_inputs_;
  std::vector<int> confirm_inputs_, reparse_inputs_;
  std::vector<std::uint8_t> mispredicted_;  // by input
  bool predict_ = true;
  PredictionCounts predictions_;
  std::uint64_t planes_ = 0;                           // bit d: display d has a compositing plane
  std::vector<router_detail::WorkerScratch> scratch_;  // one per worker
};

}  // namespace l2
