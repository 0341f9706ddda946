// The DVI path over MPI ranks, on the coordinator (display_path.hpp): the §6 sequencer runs
// here and the board columns route. Each refresh, every column is told which groups swap now
// and which frame of each input to take in; it answers with what it saw (each input's parity,
// the displays its strips reached, its frame stamp, and the frame each of its displays shows);
// from every column's answer the sequencer decides which inputs are routed and which groups
// complete, and READY goes to the pipeservers. Swap lock across machines is checked in every
// refresh.
#pragma once

#include <atomic>
#include <map>
#include <vector>

#include "dvi_link/refresh_clock.hpp"
#include "l2wall/display_path.hpp"
#include "l2wall/live_run.hpp"
#include "lightning2_emu/frame_sequencer.hpp"
#include "mpi_link/mpi_session.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "mpi_link/rank_map.hpp"
#include "swap_lock_check.hpp"

namespace l2 {

class LiveBalance;

class MpiDviPath final : public DisplayPath {
 public:
  MpiDviPath(const TileLayout& layout, const RankMap& map, MpiSession& session,
             const RunOptions& options);
  ~MpiDviPath() override { session_.stop_watching(); }
  MpiDviPath(const MpiDviPath&) = delete;
  MpiDviPath& operator=(const MpiDviPath&) = delete;

  std::string label() const override { return "dvi"; }
  std::string name() const override { return "DVI path"; }
  void add_pipeserver_args(PipeserverLaunch& launch) const override { launch.dvi = true; }
  void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
            const RunWatch& watch) override;

  bool refreshed() const override { return true; }
  std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                               std::vector<FrameRecord>& records, const RunWatch& watch) override;
  std::string pipeservers_wait_for() const override { return "READY"; }
  std::uint64_t inject_noise(PipeserverSet&) override { return 0; }  // no serial line to disturb

  DisplayPictures frame_pictures(int frame, const RunWatch& watch) override;
  std::optional<DisplayPictures> shown() const override;
  int frame_shown() const override { return shown_; }
  // The line for rank `rank` gone; from any thread.
  std::string lost_message(int rank) const;

  // A rank whose process is gone (MpiSession::lost_ranks), but for a pipeserver the run
  // survives: that one ends as a pipeserver (its RemotePipeserver is gone) and is lost.
  bool down() override;
  Status failure_as_cause(int shown, const std::string& showing) override;
  Status failure(int shown, const std::string& showing) override {
    return failure_as_cause(shown, showing);
  }

  // Waits for every pipeserver's end (its report complete), then ends the columns.
  void finish() override;
  void shut_down() override { end_columns(); }
  void add_totals(RunTotals& totals) const override;
  // A balanced run: serves the control channels as it steps and checks each swap's frames
  // share a layout. The columns do not count the strips they route, so neither does this.
  void follow_layouts(LiveBalance& balance, PipeserverSet&) override;
  // --survive-host-loss: its rank's input carries no signal from the next refresh on
  // (mpi_wire::kNoSignal in the tick). Losing the signal is news, as a new frame is: a group it
  // held up may complete now, and at full speed (--refresh 0) only news starts a refresh.
  void lose_pipeserver(int) override { unseen_ = true; }

 private:
  void check_groups_for_balance(const PipeserverSet& pipeservers);
  // Whether the run goes on when `rank` is gone: a pipeserver's, under --survive-host-loss.
  bool survived(int rank) const;
  // Says to every column, once, that `pipeserver`'s rank is gone (mpi_wire::kLost); the run's
  // end does not wait for it either.
  void tell_columns_lost(int pipeserver);
  // Takes in every pipeserver's notices of frames published; true when one is new.
  bool take_notices(PipeserverSet& pipeservers);
  // One refresh over every column; the tick's decision. A column that fails is named after
  // the others answered.
  void refresh(PipeserverSet& pipeservers);
  // After a refresh that swapped: the frame the displays keep, from the columns' answers.
  void note_swap();
  void end_columns();
  // What the columns still answering show, each waited for up to `grace` (after a fault).
  void fetch_answering(std::chrono::milliseconds grace) const;
  // Column `c`'s answer to this refresh; nullopt when it is gone or did not answer within the
  // stall timeout (stopped or hung: the pipeservers it stopped taking frames from wait on it,
  // so they are not the cause).
  std::optional<mpi_wire::Record> column_answer(int c, PipeserverSet& pipeservers);
  // The line naming column `c`, which failed refresh `index`.
  std::string column_failure(int c, std::int64_t index) const;
  std::string displays_showing() const;
  std::uint64_t groups_of_displays(std::uint64_t displays) const;

  const TileLayout& layout_;
  const RankMap& map_;
  MpiSession& session_;
  int stall_timeout_ms_;
  bool survive_;             // --survive-host-loss
  std::vector<int> gone_;    // pipeservers whose rank is gone, survived: the columns were told
  std::optional<int> lost_;  // a rank that is gone, ending the run
  int stuck_ = -1;           // a column rank that stopped answering
  RefreshClock clock_;
  double refresh_hz_;
  int frames_;
  int drop_ready_;
  std::vector<SwapGroup> groups_;
  std::map<int, int> group_of_display_;  // display id -> group index
  FrameSequencer sequencer_;
  SwapLockCheck lock_check_;
  // This refresh: what the sequencer decided, and what the columns saw.
  FrameSequencer::Decision decision_;
  std::vector<int> swapped_;
  std::vector<FrameObservation> observations_;  // by mesh input
  std::vector<int> stamps_;                     // by mesh input: the frame taken in
  std::vector<int> stamp_shown_;                // by pipeserver: the frame its stamp shows
  std::vector<int> accepted_;                   // by pipeserver: its last frame, as of the tick
  LiveBalance* balance_ = nullptr;              // a balanced run's coordinator
  std::vector<DisplayShown> displays_shown_;
  std::uint64_t refreshes_ = 0;
  std::uint64_t control_bytes_ = 0;  // refresh records to and from the columns
  bool swap_due_ = false;
  bool unseen_ = false;  // notices taken in that no refresh has taken in yet
  bool ended_ = false;
  std::atomic<int> shown_{-1};  // read by the session's watcher thread too
  std::uint64_t dropped_readies_ = 0;
  mutable std::map<int, RgbImage> pictures_;  // by display id: fetched from the columns
  mutable bool fetched_after_fault_ = false;
};

}  // namespace l2
