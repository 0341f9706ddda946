// The coordinator's warning of a machine given more ranks than cores whose MPI busy-polls.
#include "mpi_link/busy_polling.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

std::vector<RankIdentity> ranks_on(const std::string& host, int count, int cores, bool yields) {
  std::vector<RankIdentity> ranks(static_cast<std::size_t>(count));
  for (RankIdentity& r : ranks) {
    r.host = host;
    r.cores = cores;
    r.yields = yields;
  }
  return ranks;
}

TEST(BusyPolling, MoreRanksThanCoresWithoutYieldIsOneLine) {
  const auto line = busy_polling_warning(ranks_on("vm", 6, 2, false));
  ASSERT_TRUE(line);
  EXPECT_EQ(*line,
            "6 ranks on vm, which has 2 cores, busy-poll while they wait (Open MPI's "
            "mpi_yield_when_idle is off), which can make the run several times slower: add "
            "--mca mpi_yield_when_idle 1 to mpirun");
  EXPECT_EQ(line->find('\n'), std::string::npos);
}

TEST(BusyPolling, NoWarningWhenTheRanksYieldOrFit) {
  EXPECT_FALSE(busy_polling_warning(ranks_on("vm", 6, 2, true)));   // --mca ... 1, --oversubscribe
  EXPECT_FALSE(busy_polling_warning(ranks_on("vm", 2, 2, false)));  // a core each
  EXPECT_FALSE(busy_polling_warning(ranks_on("vm", 6, 0, false)));  // cores not known
  EXPECT_FALSE(busy_polling_warning({}));
}

TEST(BusyPolling, EachMachineCountedApartAndNamedInOneLine) {
  // Rank 0 and pipeservers 0-1 on render-a, 2-3 on render-b, the column on display-a.
  std::vector<RankIdentity> ranks = ranks_on("render-a", 3, 2, false);
  for (const auto& r : ranks_on("render-b", 2, 2, false)) ranks.push_back(r);
  for (const auto& r : ranks_on("display-a", 1, 1, false)) ranks.push_back(r);
  EXPECT_EQ(busy_polling_warning(ranks).value().substr(0, 45),
            "3 ranks on render-a, which has 2 cores, busy-");
  for (const auto& r : ranks_on("render-b", 2, 1, false)) ranks.push_back(r);  // now 4 on 1
  const std::string line = busy_polling_warning(ranks).value();
  EXPECT_NE(line.find("3 ranks on render-a, which has 2 cores; 4 ranks on render-b, which has 1 "
                      "core, busy-poll"),
            std::string::npos)
      << line;
  // One rank that busy-polls on a crowded machine is enough.
  std::vector<RankIdentity> mixed = ranks_on("vm", 3, 2, true);
  mixed[1].yields = false;
  EXPECT_TRUE(busy_polling_warning(mixed));
}

}  // namespace
}  // namespace l2
