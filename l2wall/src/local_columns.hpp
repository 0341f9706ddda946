// The board columns of the one-machine DVI path (board_columns.hpp): one BoardColumn in this
// process holding every display of a mesh, fed by the pipeservers' shared-memory DVI links; a
// wall of several meshes has one a mesh (tilelayout/several_meshes.hpp). The choice of one
// column is a function call away, so frames that repeat their layout are predicted rather than
// parsed (router.hpp), and a prediction that turns out wrong asks the path again. Several
// columns are decided from all their observations at once, so they parse every frame.
//
// Owns: the routing workers, the columns, the input frames taken in. It may not decide (the
// path's sequencer does) or talk to the pipeservers beyond reading their links.
#pragma once

#include <memory>
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
    return [this](int id) -> const RgbImage& { return column_of_display(id).shown(id); };
  }
  std::optional<DisplayPictures> shown() override { return pictures(); }

  std::optional<std::uint64_t> routed_strips(int input) const override {
    const BoardColumn& c = column_of_input(input);
    return c.router().scanned(c.router_input(input)).routed_strips;
  }
  void add_totals(RunTotals& totals) const override;
  std::string where() const override { return "in this process"; }
  // A wall of several meshes: which displays and pipeservers each mesh has.
  std::string summary_lines() const override { return meshes_line_; }

 private:
  const BoardColumn& column_of_display(int id) const;
  const BoardColumn& column_of_input(int pipeserver) const;

  WorkerPool pool_;
  std::vector<int> mesh_of_display_, mesh_of_input_;   // by wall display, by pipeserver
  std::vector<std::unique_ptr<BoardColumn>> columns_;  // by mesh
  std::vector<InputFrame> inputs_;                     // by pipeserver
  std::vector<Observation> seen_;                      // this refresh's: one a column
  std::string meshes_line_;
};

}  // namespace l2
