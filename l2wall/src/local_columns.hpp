// The board columns of the one-machine DVI path (board_columns.hpp): one BoardColumn in this
// process holding every display, fed by the pipeservers' shared-memory DVI links. Its choice is
// a function call away, so frames that repeat their layout are predicted rather than parsed
// (router.hpp), and a prediction that turns out wrong asks the path again.
//
// Owns: the routing workers, the column, the input frames taken in. It may not decide (the
// path's sequencer does) or talk to the pipeservers beyond reading their links.
#pragma once

#include <vector>

#include "l2wall/board_column.hpp"
#include "l2wall/board_columns.hpp"

namespace l2 {

class LocalColumns final : public BoardColumns {
 public:
  LocalColumns(const Wall& wall, int threads, std::size_t pipeservers);

  void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
            const RunWatch& watch) override {
    pipeservers.open_links(timeout, watch.processes);
  }
  bool take_in(PipeserverSet& pipeservers) override { return pipeservers.take_in(inputs_); }
  Status refresh(const Tick& tick, PipeserverSet& pipeservers, const Decide& decide,
                 const std::function<void(std::span<const Observation>)>& took) override;

  DisplayPictures pictures() override {
    return [this](int id) -> const RgbImage& { return column_.shown(id); };
  }
  std::optional<DisplayPictures> shown() override { return pictures(); }

  std::optional<std::uint64_t> routed_strips(int input) const override {
    return column_.router().scanned(input).routed_strips;
  }
  void add_totals(RunTotals& totals) const override;
  std::string where() const override { return "in this process"; }

 private:
  WorkerPool pool_;
  BoardColumn column_;
  std::vector<InputFrame> inputs_;  // by pipeserver
  std::vector<Observation> seen_;   // this refresh's: one column
};

}  // namespace l2
