// The board columns of an MPI run as the DVI path drives them (board_columns.hpp), on the
// coordinator: each column rank (column_rank.hpp) routes its own displays. A refresh sends every
// column the tick, gathers their observations, and sends them the route the path chose; a column
// that does not answer within the stall timeout is named after the others answered. The
// pipeservers' frames go straight to the columns: here only their notices arrive.
//
// Owns: the records to and from the columns, the pictures fetched from them, the losses of ranks
// (rank_losses.hpp) and what crossed the network (mpi_traffic.hpp). It may not decide: the path
// does, once, as on one machine.
#pragma once

#include <map>
#include <vector>

#include "l2wall/board_columns.hpp"
#include "l2wall/live_run.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "mpi_traffic.hpp"
#include "rank_losses.hpp"

namespace l2 {

class MpiColumns final : public BoardColumns {
 public:
  MpiColumns(const TileLayout& layout, const RankMap& map, MpiSession& session,
             const RunOptions& options);

  void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
            const RunWatch& watch) override;
  bool take_in(PipeserverSet& pipeservers) override;
  Status refresh(const Tick& tick, PipeserverSet& pipeservers, const Decide& decide,
                 const std::function<void(std::span<const Observation>)>& took) override;

  DisplayPictures pictures() override;
  std::optional<DisplayPictures> shown() override;
  void showing(int frame) override { losses_.showing(frame); }

  std::optional<std::uint64_t> routed_strips(int) const override { return std::nullopt; }
  std::string strips_not_counted() const override {
    return "the board column ranks do not count the strips they route";
  }
  std::optional<std::string> gone() override;

  void finish() override;
  void shut_down() override { end_columns(); }
  std::string where() const override {
    return "over " + std::to_string(map_.columns) + " board column rank(s)";
  }
  std::string summary_lines() const override { return traffic_.lines(control_bytes_, frames_); }

 private:
  // Column `c`'s answer; nullopt when it is gone or did not answer within the stall timeout.
  std::optional<mpi_wire::Record> answer(int c, PipeserverSet& pipeservers);
  std::string failure(int c, std::int64_t refresh) const;
  // Every column's displays into pictures_; `grace`: how long each may take (after a fault:
  // those that do not answer are left out), or wait as long as it takes.
  void fetch(std::optional<std::chrono::milliseconds> grace);
  void end_columns();

  const TileLayout& layout_;
  const RankMap& map_;
  MpiSession& session_;
  RankLosses losses_;
  MpiTraffic traffic_;
  int stall_timeout_ms_;
  int frames_;
  int stuck_ = -1;  // a column rank that stopped answering
  std::vector<Observation> seen_;
  std::uint64_t control_bytes_ = 0;  // refresh records to and from the columns
  bool ended_ = false;
  bool fetched_after_fault_ = false;
  std::map<int, RgbImage> pictures_;  // by display id: fetched from the columns
};

}  // namespace l2
