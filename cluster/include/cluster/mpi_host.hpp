// A pipeserver's DVI link and back-channel in an MPI run: its frames to the board columns its
// tiles land on, its READYs from the coordinator.
#pragma once

#include <cstdint>
#include <memory>

#include "dvi_link/dvi_link.hpp"
#include "sync_backchannel/ready_channel.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct MpiHostLinks {
  std::unique_ptr<DviSender> link;
  std::unique_ptr<ReadyChannel> channel;
};

// For pipeserver `server` of `layout`; MPI must be initialised (MpiSession). `bytes_sent`
// counts the bytes of the frames it sends.
MpiHostLinks mpi_host_links(const TileLayout& layout, int server,
                            std::shared_ptr<std::uint64_t> bytes_sent);

// Tells the coordinator this host ended well, its report written (it reads the reports next),
// and how many bytes of frames it sent.
void report_host_done(std::uint64_t bytes_sent);

}  // namespace l2
