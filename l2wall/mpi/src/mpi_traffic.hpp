// What crossed the network in an MPI run, for the summary: each pipeserver's bytes of DVI frames
// and of tiles (its last word, mpi_wire::kDone, sent once its report is complete) and the
// refresh records between the coordinator and the columns.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "mpi_link/mpi_dvi_link.hpp"
#include "mpi_link/rank_map.hpp"

namespace l2 {

class MpiTraffic {
 public:
  // Waits up to 10 s for the last word of every pipeserver but those `gone` (they send nothing
  // more). Throws RunFault naming one that does not end.
  void take_done(const RankMap& map, std::span<const int> gone);
  // "network: ..." lines, each ending in a newline.
  std::string lines(std::uint64_t control_bytes, int frames) const;

 private:
  SentBytes frames_, tiles_;
};

}  // namespace l2
