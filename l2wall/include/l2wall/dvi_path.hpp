// The DVI path as a display path (display_path.hpp), written once for every backend: the
// emulated Lightning-2 paced by its refresh clock. At each refresh it tells the board columns
// (board_columns.hpp: in this process, or column ranks over MPI) which groups swap and which
// frame each input carries, decides from what they saw which inputs are routed and which groups
// complete (the §6 frame sequencer), sends READY in the refresh a frame completed (spec §6.4),
// and knows from the stamps the columns followed into the displays which frame they show.
//
// Owns: the frame sequencer, the refresh clock, READY, the balance hooks (the control channels
// served while stepping, every swap checked against the layouts), the frame-shown rule, the
// swap-lock check and, for a wall with [displays], the record of frame lock (what each display
// showed by its own refresh clock, frame_lock_record.hpp) and, for an active stereo wall, the
// quad buffer after the columns (quad_buffer.hpp: it copies each eye frame the displays take in
// and shows a whole pair, one eye per refresh) with its proof. It may not touch the routed
// pixels or the transport: the columns route, and say what they saw.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "dvi_link/refresh_clock.hpp"
#include "l2wall/active_stereo_check.hpp"
#include "l2wall/board_columns.hpp"
#include "l2wall/colour_stage.hpp"
#include "l2wall/display_path.hpp"
#include "l2wall/frame_lock_record.hpp"
#include "l2wall/live_run.hpp"
#include "l2wall/packed_stereo_record.hpp"
#include "l2wall/quad_buffer.hpp"
#include "l2wall/swap_lock_check.hpp"
#include "lightning2_emu/frame_sequencer.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// The frame a pipeserver's part of the displays shows, its last frame being `last`: `last` if
// the display of its last frame's first tile shows that frame's stamp, else the one before if
// the display of that frame's first tile shows its stamp, else whatever the first shows (a
// balanced run may have moved its tiles between them). `seen_last`, `seen_before`: the stamps of
// its input frames those displays show (board_column.hpp), kStampNotHere where no column holds
// them or they show nothing of it. Nullopt when neither was read.
std::optional<int> shown_by_stamps(int last, int seen_last, int seen_before);

class DviPath final : public DisplayPath {
 public:
  DviPath(const TileLayout& layout, const RunOptions& options,
          std::unique_ptr<BoardColumns> columns);

  std::string label() const override { return "dvi"; }
  std::string name() const override { return "DVI path"; }
  void add_pipeserver_args(PipeserverLaunch& launch) const override { launch.dvi = true; }
  void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
            const RunWatch& watch) override;

  bool refreshed() const override { return true; }
  std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                               std::vector<FrameRecord>& records, const RunWatch& watch) override;
  std::string pipeservers_wait_for() const override { return "READY"; }
  std::uint64_t inject_noise(PipeserverSet& pipeservers) override {
    return pipeservers.inject_noise();
  }

  // The columns' front buffers, colour matched as they leave (colour_stage.hpp).
  DisplayPictures frame_pictures(int frame, const RunWatch&) override {
    return colour_.apply(columns_->pictures(), frame);
  }
  // An active stereo wall's: what the quad buffer shows in the last refresh, once it has a pair.
  std::optional<DisplayPictures> shown() const override {
    if (quad_ && quad_->shown().front().frame >= 0)
      return colour_.apply([this](int id) -> const RgbImage& { return quad_->picture(id); });
    auto pictures = columns_->shown();
    if (!pictures) return std::nullopt;
    return colour_.apply(std::move(*pictures));
  }
  int frame_shown() const override { return shown_; }
  // A wall with [displays]: frame-lock.txt, the frame each display shows by its own clock.
  std::vector<std::pair<std::string, std::string>> frame_files() const override {
    if (!frame_lock_) return {};
    return {{"frame-lock.txt", frame_lock_->shown_lines()}};
  }

  bool down() override { return columns_->gone().has_value(); }
  Status failure_as_cause(int, const std::string&) override;
  Status failure(int shown, const std::string& showing) override {
    return failure_as_cause(shown, showing);
  }

  void finish() override;
  void shut_down() override { columns_->shut_down(); }
  void add_totals(RunTotals& totals) const override;
  // What the path proved once every frame is shown (swap lock in every refresh) and the
  // columns' own lines; empty before.
  std::string summary_lines() const;
  void follow_layouts(LiveBalance& balance, PipeserverSet& pipeservers) override;
  // Losing a signal is news, as a new frame is: a group it held up may complete now, and at
  // full speed (--refresh 0) only news starts a refresh.
  void lose_pipeserver(int pipeserver) override {
    columns_->lose(pipeserver);
    unseen_ = true;
  }

 private:
  // One refresh over the columns: the tick, their observations, the sequencer's decision.
  void refresh(PipeserverSet& pipeservers);
  Tick make_tick(std::int64_t index, const PipeserverSet& pipeservers);
  // What every column saw, by mesh input and by pipeserver; throws RunFault for an observation
  // naming a pipeserver the wall lacks.
  void take(std::span<const Observation> seen, const PipeserverSet& pipeservers);
  const ColumnRoute& decide(std::span<const Observation> seen, const PipeserverSet& pipeservers);
  // After a refresh that swapped: the frame the displays keep.
  void note_swap();
  // The groups (bits) of the displays (bits of mesh `mesh`'s display ids).
  std::uint64_t groups_of_displays(int mesh, std::uint64_t displays) const;
  // An active stereo wall: the quad buffer's refresh `index` after the columns', and its check.
  void refresh_quad(std::uint64_t index);
  // The summary's line of an active stereo wall's pairs; empty for any other wall.
  std::string active_stereo_line() const;
  void count_for_balance(PipeserverSet& pipeservers);
  void check_groups_for_balance(const PipeserverSet& pipeservers);

  std::unique_ptr<BoardColumns> columns_;
  ColourStage colour_;
  RefreshClock clock_;
  double refresh_hz_;
  int frames_;
  int drop_ready_;
  std::vector<SwapGroup> groups_;
  // By mesh: the mesh's display id -> group index.
  std::vector<std::map<int, int>> group_of_display_;
  FrameSequencer sequencer_;
  SwapLockCheck lock_check_;
  std::optional<FrameLockRecord> frame_lock_;  // a wall with [displays]
  int eye_pairs_ = 0;  // a passive stereo wall's twin pairs, which lock_check_ also proves
  // An active stereo wall's quad buffer, and its proof that every refresh shows the eye of its
  // parity of one frame (with stereo-refreshes.csv, each refresh's eye and frame).
  std::optional<QuadBuffer> quad_;
  std::optional<ActiveStereoCheck> active_check_;
  // A packed stereo wall's proof that each display's halves show one frame, both eyes.
  std::optional<PackedStereoRecord> packed_;
  // This refresh: what the sequencer decided, and what the columns saw.
  std::vector<int> swapped_;
  FrameSequencer::Decision decision_;
  ColumnRoute route_;
  std::vector<FrameObservation> observations_;  // by mesh input
  std::vector<int> stamps_;                     // by mesh input: the frame taken in
  std::vector<int> stamp_shown_;                // by pipeserver: the frame its stamp shows
  std::vector<int> accepted_;                   // by pipeserver: its last frame, as of the tick
  std::vector<DisplayShown> displays_shown_;
  LiveBalance* balance_ = nullptr;  // a balanced run's coordinator
  std::uint64_t refreshes_ = 0;
  std::uint64_t dropped_readies_ = 0;
  bool swap_due_ = false;
  bool unseen_ = false;    // news no refresh has taken in yet (first frames, a signal lost)
  bool finished_ = false;  // every frame shown and the columns ended well
  int shown_ = -1;         // the frame the displays show
};

}  // namespace l2
