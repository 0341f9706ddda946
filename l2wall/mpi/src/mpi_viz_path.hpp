// The viz path over MPI ranks, on the coordinator (display_path.hpp): the
// pipeservers send their tiles to the board column owning each display, and every column
// composites its displays (distributed compositing, the compositing server's rules). Once every
// column has composed a frame, SWAPPED goes to the pipeservers. Runs beside the DVI path (--path
// both), whose swaps lead; each of its frames is fetched from the columns to be compared.
#pragma once

#include <map>
#include <vector>

#include "l2wall/display_path.hpp"
#include "mpi_link/rank_map.hpp"

namespace l2 {

class MpiVizPath final : public DisplayPath {
 public:
  MpiVizPath(const TileLayout& layout, const RankMap& map, int stall_timeout_ms);

  std::string label() const override { return "vizserver"; }
  std::string name() const override { return "vizserver path"; }
  void add_pipeserver_args(PipeserverLaunch&) const override {
  }  // the ranks were started with theirs
  void open(PipeserverSet&, std::chrono::milliseconds, const RunWatch&) override {}

  // Never the lead over MPI (--path vizserver alone is refused).
  bool refreshed() const override { return false; }
  std::optional<PathSwap> step(int, PipeserverSet&, std::vector<FrameRecord>&,
                               const RunWatch&) override {
    return std::nullopt;
  }
  std::string pipeservers_wait_for() const override { return "SWAPPED"; }
  std::uint64_t inject_noise(PipeserverSet&) override { return 0; }

  DisplayPictures frame_pictures(int frame, const RunWatch& watch) override;
  // The columns composited `frame`; their pictures stay where they are (not over the network).
  void take_frame(int frame, const RunWatch& watch) override;
  std::optional<DisplayPictures> shown() const override;
  int frame_shown() const override { return fetched_; }

  // Never down by itself; asked at every check of the run, so it also takes in what the
  // columns composed and sends SWAPPED.
  bool down() override;

  void add_totals(RunTotals&) const override {}

 private:
  void pump();

  const TileLayout& layout_;
  const RankMap& map_;
  int stall_timeout_ms_;
  std::vector<long> composed_;  // by column: the last frame it composed (-1: none)
  long swapped_ = -1;           // SWAPPED sent for frames up to this one
  int fetched_ = -1;
  std::map<int, RgbImage> pictures_;  // by display id: frame fetched_
};

}  // namespace l2
