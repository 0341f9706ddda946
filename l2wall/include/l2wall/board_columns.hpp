// The board columns of a live run's Lightning-2 as the DVI path (dvi_path.hpp) drives them: take
// in what the pipeservers delivered, then at each refresh swap, scan, answer what they saw, and
// route and complete what the path decided. Two implementations sit beside each other: the
// columns in this process over the pipeservers' shared-memory links (local_columns.hpp: one
// column holding every display) and the column ranks of an MPI run (mpi/src/mpi_columns.hpp,
// records over MPI). Everything that is the same on both (the frame sequencer, the refresh
// clock, READY, balancing, the frame-shown rule, swap lock) is the path's, written once.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"
#include "l2wall/display_path.hpp"

namespace l2 {

class BoardColumns {
 public:
  virtual ~BoardColumns() = default;

  // Before the first refresh: waits (up to `timeout`, watched) until every pipeserver's input
  // carries a signal. Throws RunFault naming those still silent.
  virtual void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
                    const RunWatch& watch) = 0;
  // Takes in what the pipeservers published since the last refresh (LivePipeserver::sequence);
  // true when something is new.
  virtual bool take_in(PipeserverSet& pipeservers) = 0;

  // The path's choice from every column's observation of a refresh: the route. It may be asked
  // twice in one refresh (a predicted layout that turned out different, router.hpp), so it
  // decides from `seen` alone.
  using Decide = std::function<const ColumnRoute&(std::span<const Observation> seen)>;
  // One refresh: the columns swap `tick`'s groups, scan their inputs, and route and complete
  // what `decide` chose from their observations. A column that did not answer is the failure
  // returned, its line worded after `took` was given what the others saw (what the displays keep
  // is known then, showing()); `decide` is not asked.
  virtual Status refresh(const Tick& tick, PipeserverSet& pipeservers, const Decide& decide,
                         const std::function<void(std::span<const Observation>)>& took) = 0;

  // The displays' pictures as they are now (fetched from far columns).
  virtual DisplayPictures pictures() = 0;
  // What the displays show now, if anything reached them. Over MPI it is asked after a fault
  // only: what the columns still answering show, empty pictures for the others.
  virtual std::optional<DisplayPictures> shown() = 0;
  // The frame the displays keep now, for the columns' own messages (from any thread).
  virtual void showing(int /*frame*/) {}

  // Strips routed from input `input` in the last refresh; nullopt where the columns do not count
  // them (then `strips_not_counted()` says why).
  virtual std::optional<std::uint64_t> routed_strips(int input) const = 0;
  virtual std::string strips_not_counted() const { return {}; }

  // --survive-host-loss: `pipeserver` is lost; its input carries no signal from now on.
  virtual void lose(int /*pipeserver*/) {}
  // A column (or a rank the run cannot go on without) is gone; nullopt while all is well. Asked
  // at every check of the run.
  virtual std::optional<std::string> gone() { return std::nullopt; }

  // After the last frame: what must end with the run ends (over MPI: every pipeserver's
  // report is complete, then the column ranks). Throws RunFault for one that does not.
  virtual void finish() {}
  // Ends the columns, if they are processes of their own.
  virtual void shut_down() {}
  // Counts for the report.
  virtual void add_totals(RunTotals& /*totals*/) const {}
  // Where the columns ran, for the summary: "in this process", "over 2 board column rank(s)".
  virtual std::string where() const = 0;
  // Lines of their own for the summary (what crossed the network), each ending in a newline.
  virtual std::string summary_lines() const { return {}; }
};

}  // namespace l2
