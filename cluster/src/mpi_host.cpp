#include "cluster/mpi_host.hpp"

#include "cluster/mpi_dvi_link.hpp"
#include "cluster/mpi_ready_channel.hpp"
#include "cluster/mpi_wire.hpp"
#include "cluster/rank_map.hpp"

namespace l2 {

MpiHostLinks mpi_host_links(const TileLayout& layout, int server,
                            std::shared_ptr<std::uint64_t> bytes_sent) {
  const RankMap map = make_rank_map(layout);
  std::vector<int> ranks;
  for (const int c : map.columns_of_server[static_cast<std::size_t>(server)])
    ranks.push_back(map.column_rank(c));
  const ServerPlan& plan = layout.servers[static_cast<std::size_t>(server)];
  MpiHostLinks links;
  links.link = std::make_unique<MpiDviSender>(std::move(ranks), RankMap::kCoordinator,
                                              plan.fb_width, plan.fb_height, std::move(bytes_sent));
  links.channel =
      std::make_unique<MpiReadyChannel>(RankMap::kCoordinator, "MPI rank 0 (coordinator)");
  return links;
}

void report_host_done(std::uint64_t bytes_sent) {
  mpi_wire::send({static_cast<std::int64_t>(bytes_sent)}, RankMap::kCoordinator, mpi_wire::kDone);
}

}  // namespace l2
