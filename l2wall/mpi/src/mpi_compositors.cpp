#include "mpi_compositors.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <thread>

#include "lightning2_emu/mesh.hpp"
#include "mpi_link/mpi_wire.hpp"

namespace l2 {

MpiCompositors::MpiCompositors(const TileLayout& layout, const RankMap& map, int stall_timeout_ms)
    : layout_(layout),
      map_(map),
      stall_timeout_ms_(stall_timeout_ms),
      composed_(static_cast<std::size_t>(map.columns), -1) {}

void MpiCompositors::pump() {
  for (int c = 0; c < map_.columns; ++c) {
    const int rank = map_.column_rank(c);
    while (mpi_wire::waiting(rank, mpi_wire::kComposed)) {
      const auto r = mpi_wire::receive(rank, mpi_wire::kComposed);
      composed_[static_cast<std::size_t>(c)] = static_cast<long>(mpi_wire::Reader(r).next());
    }
  }
  // Swap lock of this path: a frame is swapped once every column has composed it.
  const long everywhere = *std::min_element(composed_.begin(), composed_.end());
  if (everywhere <= swapped_) return;
  swapped_ = everywhere;
  for (int s = 0; s < map_.pipeservers; ++s)
    mpi_wire::send({swapped_}, map_.pipeserver_rank(s), mpi_wire::kSwapped);
}

bool MpiCompositors::composed(int frame, std::chrono::milliseconds wait) {
  const auto deadline = RunClock::now() + wait;
  for (;;) {
    pump();
    if (swapped_ >= frame) return true;
    if (RunClock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

std::string MpiCompositors::late(int frame) const {
  return fmt::format(
      "the board columns did not composite frame {} within {} ms (vizserver path over MPI)", frame,
      stall_timeout_ms_);
}

DisplayPictures MpiCompositors::pictures(int frame) {
  if (frame != fetched_) {
    for (int c = 0; c < map_.columns; ++c)
      mpi_wire::send({mpi_wire::kFetchComposed, frame}, map_.column_rank(c), mpi_wire::kCommand);
    for (int c = 0; c < map_.columns; ++c) {
      for (const Display& d : layout_.wall.displays) {
        if (map_.column_of_display[static_cast<std::size_t>(d.id)] != c) continue;
        RgbImage& picture = pictures_[d.id];
        if (picture.empty()) picture = RgbImage(d.width, d.height);
        mpi_wire::receive_bytes(picture.bytes(), map_.column_rank(c), mpi_wire::kPicture);
      }
    }
    fetched_ = frame;
  }
  return [this](int id) -> const RgbImage& { return pictures_.at(id); };
}

std::optional<DisplayPictures> MpiCompositors::shown() const {
  if (fetched_ < 0) return std::nullopt;
  return [this](int id) -> const RgbImage& { return pictures_.at(id); };
}

}  // namespace l2
