// A pipeserver's DVI link and back-channel in an MPI run: its frames to the board columns its
// tiles land on, its READYs from the coordinator.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "dvi_link/dvi_link.hpp"
#include "mpi_link/mpi_dvi_link.hpp"
#include "sync_backchannel/ready_channel.hpp"
#include "tilelayout/tile_layout.hpp"
#include "viz_link/tile_delta.hpp"
#include "viz_link/tile_sender.hpp"

namespace l2 {

struct MpiRankLinks {
  std::unique_ptr<DviSender> link;
  std::unique_ptr<ReadyChannel> channel;
};

// How frames and tiles travel to each rank: `asked` (--link-codec) when given; else ("auto")
// zstd to a rank on another machine, and whole to one on this machine, where copying costs
// less than predicting and compressing.
using CodecTo = std::function<LinkCodec(int rank)>;
CodecTo codec_to(std::optional<LinkCodec> asked, std::function<bool(int rank)> beside);

// For pipeserver `pipeserver` of `layout`; MPI must be initialised (MpiSession). Frames go
// encoded with `codec(rank)` for each column rank (frame_delta.hpp); `bytes_sent` counts their
// bytes. `every_column`: a balanced run's, whose frames go whole to every board column
// (make_rank_map).
MpiRankLinks mpi_rank_links(const TileLayout& layout, int pipeserver, const CodecTo& codec,
                            std::shared_ptr<SentBytes> bytes_sent, bool every_column = false);

// The viz path over MPI, pipeserver side: each tile to the board column owning its
// display, the end of each frame to every column (with the number of tiles it sent that
// column), SWAPPED from the coordinator.
class MpiTileSender {
 public:
  // Tiles go as what changed since their last frame (tile_delta.hpp), compressed with `codec`;
  // `bytes_sent` counts the bytes of the tiles it sends, raw and as tile messages.
  MpiTileSender(const TileLayout& layout, const CodecTo& codec,
                std::shared_ptr<SentBytes> bytes_sent);
  void send_tile(std::uint32_t frame, const viz::TileTarget& tile, const std::uint8_t* rgb,
                 std::size_t stride);
  void finish_frame(std::uint32_t frame, std::uint32_t tiles_sent);
  // Throws std::runtime_error when no SWAPPED for `frame` (or later) came within `timeout`.
  void wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout);

 private:
  std::vector<int> column_ranks_;
  std::vector<int> column_of_display_;  // by display id (RankMap)
  std::vector<std::uint32_t> sent_;     // by column: tiles of the open frame sent there
  std::vector<std::uint8_t> message_;
  std::vector<viz::TileDeltaEncoder> deltas_;  // by column
  std::vector<bool> whole_;  // by column: its tiles go whole, as kTileKind messages
  std::optional<std::uint32_t> swapped_;
  std::shared_ptr<SentBytes> bytes_sent_;
};

// Tells the coordinator this pipeserver ended well, its report written (it reads the reports next),
// and how many bytes of frames (raw and on the wire) and of tiles it sent.
void report_rank_done(const SentBytes& frames, const SentBytes& tiles);

}  // namespace l2
