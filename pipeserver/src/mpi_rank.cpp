#include "mpi_rank.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <cstring>
#include <stdexcept>
#include <thread>

#include "lightning2_emu/mesh.hpp"
#include "mpi_link/mpi_dvi_link.hpp"
#include "mpi_link/mpi_ready_channel.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "mpi_link/rank_map.hpp"

namespace l2 {

namespace {

// The payload of every tile of `plan` on another column's displays: that column routes none of
// it, so it travels black. What the column does read stays: every header (the router reads
// each of a row) and the frame stamp, the first pixel of the first tile (pipeserver_set.hpp).
std::vector<BlankRect> other_columns_strips(const RankMap& map, const PipeserverPlan& plan,
                                            int column) {
  std::vector<BlankRect> out;
  for (std::size_t i = 0; i < plan.tiles.size(); ++i) {
    const PackedTile& t = plan.tiles[i];
    if (map.column_of_display[static_cast<std::size_t>(t.tile.display)] == column) continue;
    const int w = payload_columns(t.tile), h = t.tile.on_display.h;
    if (i == 0) {
      out.push_back({t.fb_x + 1, t.fb_y, w - 1, 1});
      out.push_back({t.fb_x, t.fb_y + 1, w, h - 1});
    } else {
      out.push_back({t.fb_x, t.fb_y, w, h});
    }
  }
  return out;
}

}  // namespace

CodecTo codec_to(std::optional<LinkCodec> asked, std::function<bool(int rank)> beside) {
  return [asked, beside = std::move(beside)](int rank) {
    return asked ? *asked : beside(rank) ? LinkCodec::Whole : LinkCodec::Zstd;
  };
}

MpiRankLinks mpi_rank_links(const TileLayout& layout, int pipeserver, const CodecTo& codec,
                            std::shared_ptr<SentBytes> bytes_sent, bool every_column) {
  const RankMap map = make_rank_map(layout, every_column);
  const PipeserverPlan& plan = layout.pipeservers[static_cast<std::size_t>(pipeserver)];
  std::vector<ColumnFeed> columns;
  for (const int c : map.columns_of_pipeserver[static_cast<std::size_t>(pipeserver)]) {
    const int rank = map.column_rank(c);
    const LinkCodec how = codec(rank);
    // A balanced run's layouts move tiles between columns: every column gets every strip. A
    // whole frame costs the same with black strips as without.
    const bool blank = !every_column && how != LinkCodec::Whole;
    columns.push_back(
        {rank, how, blank ? other_columns_strips(map, plan, c) : std::vector<BlankRect>{}});
  }
  MpiRankLinks links;
  links.link = std::make_unique<MpiDviSender>(std::move(columns), RankMap::kCoordinator,
                                              plan.fb_width, plan.fb_height, std::move(bytes_sent));
  links.channel =
      std::make_unique<MpiReadyChannel>(RankMap::kCoordinator, "MPI rank 0 (coordinator)");
  return links;
}

MpiTileSender::MpiTileSender(const TileLayout& layout, const CodecTo& codec,
                             std::shared_ptr<SentBytes> bytes_sent)
    : bytes_sent_(std::move(bytes_sent)) {
  const RankMap map = make_rank_map(layout);
  column_of_display_ = map.column_of_display;
  for (int c = 0; c < map.columns; ++c) {
    column_ranks_.push_back(map.column_rank(c));
    whole_.push_back(codec(map.column_rank(c)) == LinkCodec::Whole);
    deltas_.emplace_back(codec(map.column_rank(c)));
  }
  sent_.assign(column_ranks_.size(), 0);
}

void MpiTileSender::send_tile(std::uint32_t frame, const viz::TileTarget& t,
                              const std::uint8_t* rgb, std::size_t stride) {
  const auto column =
      static_cast<std::size_t>(column_of_display_.at(static_cast<std::size_t>(t.display)));
  mpi_wire::TileMessage m{whole_[column] ? mpi_wire::kTileKind : mpi_wire::kTileDeltaKind,
                          frame,
                          static_cast<std::uint32_t>(t.display),
                          t.x,
                          t.y,
                          static_cast<std::uint32_t>(t.w),
                          static_cast<std::uint32_t>(t.h),
                          0,
                          static_cast<std::uint32_t>(t.how),
                          t.key};
  const viz::TileHeader h{frame, m.display, m.dx, m.dy, m.w, m.h, t.how, t.key};
  if (whole_[column]) {  // the rows themselves, gathered once into the message
    const std::size_t row = h.row_bytes();
    message_.resize(sizeof m + h.pixel_bytes());
    for (std::uint32_t r = 0; r < h.h; ++r)
      std::memcpy(message_.data() + sizeof m + row * r, rgb + stride * r, row);
  } else {
    const std::span<const std::uint8_t> encoded = deltas_[column].encode(h, rgb, stride);
    message_.resize(sizeof m + encoded.size());
    std::memcpy(message_.data() + sizeof m, encoded.data(), encoded.size());
  }
  std::memcpy(message_.data(), &m, sizeof m);
  const int to = column_ranks_[column];
  ++sent_[column];
  mpi_wire::send_bytes(message_, to, mpi_wire::kTile);
  bytes_sent_->raw += sizeof m + h.pixel_bytes();
  bytes_sent_->wire += message_.size();
  if (frame == 0) bytes_sent_->first_wire += message_.size();
}

void MpiTileSender::finish_frame(std::uint32_t frame, std::uint32_t) {
  for (viz::TileDeltaEncoder& d : deltas_) d.end_frame();
  for (std::size_t c = 0; c < column_ranks_.size(); ++c) {
    const int to = column_ranks_[c];
    const mpi_wire::TileMessage m{mpi_wire::kFrameDoneKind, frame, 0, 0, 0, 0, 0, sent_[c], 0, 0};
    sent_[c] = 0;
    if (MPI_Send(&m, sizeof m, MPI_BYTE, to, mpi_wire::kTile, MPI_COMM_WORLD) != MPI_SUCCESS)
      throw std::runtime_error(fmt::format("sending the end of a frame to rank {} failed", to));
    bytes_sent_->raw += sizeof m;
    bytes_sent_->wire += sizeof m;
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

void report_rank_done(const SentBytes& frames, const SentBytes& tiles) {
  mpi_wire::send(
      {static_cast<std::int64_t>(frames.raw), static_cast<std::int64_t>(frames.wire),
       static_cast<std::int64_t>(frames.first_wire), static_cast<std::int64_t>(tiles.raw),
       static_cast<std::int64_t>(tiles.wire), static_cast<std::int64_t>(tiles.first_wire)},
      RankMap::kCoordinator, mpi_wire::kDone);
}

}  // namespace l2
