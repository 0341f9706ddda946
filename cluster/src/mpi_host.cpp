#include "cluster/mpi_host.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cstring>
#include <stdexcept>
#include <thread>

#include "cluster/mpi_dvi_link.hpp"
#include "cluster/mpi_ready_channel.hpp"
#include "cluster/mpi_wire.hpp"
#include "cluster/rank_map.hpp"
#include "lightning2_emu/mesh.hpp"

namespace l2 {

MpiHostLinks mpi_host_links(const TileLayout& layout, int pipeserver,
                            std::shared_ptr<std::uint64_t> bytes_sent, bool every_column) {
  const RankMap map = make_rank_map(layout, every_column);
  std::vector<int> ranks;
  for (const int c : map.columns_of_pipeserver[static_cast<std::size_t>(pipeserver)])
    ranks.push_back(map.column_rank(c));
  const PipeserverPlan& plan = layout.pipeservers[static_cast<std::size_t>(pipeserver)];
  MpiHostLinks links;
  links.link = std::make_unique<MpiDviSender>(std::move(ranks), RankMap::kCoordinator,
                                              plan.fb_width, plan.fb_height, std::move(bytes_sent));
  links.channel =
      std::make_unique<MpiReadyChannel>(RankMap::kCoordinator, "MPI rank 0 (coordinator)");
  return links;
}

MpiTileSender::MpiTileSender(const TileLayout& layout, std::shared_ptr<std::uint64_t> bytes_sent)
    : bytes_sent_(std::move(bytes_sent)) {
  const RankMap map = make_rank_map(layout);
  for (int c = 0; c < map.columns; ++c) column_ranks_.push_back(map.column_rank(c));
  sent_.assign(column_ranks_.size(), 0);
}

void MpiTileSender::send_tile(std::uint32_t frame, const viz::TileTarget& t,
                              const std::uint8_t* rgb, std::size_t stride) {
  mpi_wire::TileMessage m{mpi_wire::kTileKind,
                          frame,
                          static_cast<std::uint32_t>(t.display),
                          t.x,
                          t.y,
                          static_cast<std::uint32_t>(t.w),
                          static_cast<std::uint32_t>(t.h),
                          0,
                          static_cast<std::uint32_t>(t.how),
                          t.key};
  const std::size_t row =
      static_cast<std::size_t>(t.w) * 3 * (t.how == viz::TileKind::Depth ? 2 : 1);
  message_.resize(sizeof m + row * static_cast<std::size_t>(t.h));
  std::memcpy(message_.data(), &m, sizeof m);
  for (int y = 0; y < t.h; ++y)
    std::memcpy(message_.data() + sizeof m + row * static_cast<std::size_t>(y),
                rgb + stride * static_cast<std::size_t>(y), row);
  const auto column = static_cast<std::size_t>(Mesh::column_of_display(t.display));
  const int to = column_ranks_[column];
  ++sent_[column];
  if (MPI_Send(message_.data(), static_cast<int>(message_.size()), MPI_BYTE, to, mpi_wire::kTile,
               MPI_COMM_WORLD) != MPI_SUCCESS)
    throw std::runtime_error(fmt::format("sending a tile to rank {} failed", to));
  *bytes_sent_ += message_.size();
}

void MpiTileSender::finish_frame(std::uint32_t frame, std::uint32_t) {
  for (std::size_t c = 0; c < column_ranks_.size(); ++c) {
    const int to = column_ranks_[c];
    const mpi_wire::TileMessage m{mpi_wire::kFrameDoneKind, frame, 0, 0, 0, 0, 0, sent_[c], 0, 0};
    sent_[c] = 0;
    if (MPI_Send(&m, sizeof m, MPI_BYTE, to, mpi_wire::kTile, MPI_COMM_WORLD) != MPI_SUCCESS)
      throw std::runtime_error(fmt::format("sending the end of a frame to rank {} failed", to));
    *bytes_sent_ += sizeof m;
  }
}

void MpiTileSender::wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!swapped_ || *swapped_ < frame) {
    if (mpi_wire::waiting(RankMap::kCoordinator, mpi_wire::kSwapped)) {
      const auto r = mpi_wire::receive(RankMap::kCoordinator, mpi_wire::kSwapped);
      swapped_ = static_cast<std::uint32_t>(mpi_wire::Reader(r).next());
      continue;
    }
    if (std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error(fmt::format(
          "no SWAPPED for frame {} from the coordinator within {} ms", frame, timeout.count()));
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

void report_host_done(std::uint64_t frame_bytes, std::uint64_t tile_bytes) {
  mpi_wire::send({static_cast<std::int64_t>(frame_bytes), static_cast<std::int64_t>(tile_bytes)},
                 RankMap::kCoordinator, mpi_wire::kDone);
}

}  // namespace l2
