// The compositors of the viz path over MPI (compositors.hpp), on the coordinator: the
// pipeservers send their tiles to the board column owning each display, and every column
// composites its displays (the compositing server's rules). Once every column has composed a
// frame, SWAPPED goes to the pipeservers. Runs beside the DVI path (--path both), whose swaps
// lead; each of its frames is fetched from the columns only when it is compared or kept.
//
// Owns: what each column composed, SWAPPED, the pictures fetched. It may not lead a run.
#pragma once

#include <map>
#include <vector>

#include "l2wall/compositors.hpp"
#include "mpi_link/rank_map.hpp"

namespace l2 {

class MpiCompositors final : public Compositors {
 public:
  MpiCompositors(const TileLayout& layout, const RankMap& map, int stall_timeout_ms);

  bool composed(int frame, std::chrono::milliseconds wait) override;
  DisplayPictures pictures(int frame) override;
  std::optional<DisplayPictures> shown() const override;
  int frame_shown() const override { return fetched_; }
  std::optional<std::chrono::milliseconds> frame_limit() const override {
    return std::chrono::milliseconds(stall_timeout_ms_);
  }
  std::string late(int frame) const override;
  // Never down by itself; asked at every check of the run, so it also takes in what the
  // columns composed and sends SWAPPED.
  bool down() override {
    pump();
    return false;
  }

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
