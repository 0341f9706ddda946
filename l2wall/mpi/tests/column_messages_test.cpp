#include "column_messages.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace l2 {
namespace {

Tick two_pipeserver_tick() {
  Tick t;
  t.refresh = 41;
  t.swapped_groups = {0, 2};
  t.sequences = {17, std::numeric_limits<std::uint64_t>::max() >> 1};
  t.stamps = {{{3, 4, 0, 5, 6}, {7, 8, 1, 9, 10}, {11, 12, 2, 13, 14}},
              {{0, 1, 63, 2, 3}, {4, 5, 62, 6, 7}, {8, 9, 61, 10, 11}}};
  return t;
}

Observation five() {
  Observation o;
  o.refresh = 5;
  o.mesh = 3;
  return o;
}

TEST(ColumnMessages, TickRoundTripsAfterItsCommandWord) {
  const Tick sent = two_pipeserver_tick();
  const mpi_wire::Record r = encode(sent);
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.front(), mpi_wire::kTick);
  // kTick, refresh, 2 groups, 2 sequences, 2 hosts of 3 spots of 5 words.
  EXPECT_EQ(r.size(), 1u + 1 + (1 + 2) + (1 + 2) + (1 + 2 * 15));
  mpi_wire::Reader in(r);
  EXPECT_EQ(in.next(), mpi_wire::kTick);
  EXPECT_EQ(decode_tick(in), sent);
  EXPECT_TRUE(in.done());
}

TEST(ColumnMessages, ObservationRoundTrips) {
  Observation sent;
  sent.refresh = 9;
  sent.inputs = {{0, true, false, true, 1, 0x8000000000000001ull, 12},
                 {3, false, true, false, 0, 0, -1}};
  sent.stamps = {{1, 11, kStampNotHere}, {3, kStampNotHere, 10}};
  sent.displays = {{8, 11, 0, 10}, {9, -1, 0, -1}};  // the rank is the receiver's to fill
  EXPECT_EQ(decode_observation(encode(sent)), sent);
}

// The refresh, the column's mesh and three counts of none.
TEST(ColumnMessages, EmptyObservationIsFiveWords) {
  const mpi_wire::Record r = encode(five());
  EXPECT_EQ(r, (mpi_wire::Record{5, 3, 0, 0, 0}));
  EXPECT_EQ(decode_observation(r), five());
}

TEST(ColumnMessages, AMeshOutOfRangeIsRefused) {
  for (const std::int64_t mesh : {std::int64_t{-1}, std::int64_t{16}}) {
    EXPECT_THROW(decode_observation(mpi_wire::Record{7, mesh, 0, 0, 0}), std::runtime_error)
        << mesh;
  }
}

TEST(ColumnMessages, CutRecordsAreRefused) {
  const mpi_wire::Record whole = encode(two_pipeserver_tick());
  for (std::size_t size = 1; size < whole.size(); ++size) {
    const mpi_wire::Record cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(size));
    mpi_wire::Reader in(cut);
    in.next();
    EXPECT_THROW(decode_tick(in), std::runtime_error) << "cut to " << size << " words";
  }
}

TEST(ColumnMessages, AHugeOrNegativeCountIsRefusedBeforeAnyAllocation) {
  for (const std::int64_t count : {std::int64_t{1} << 60, std::int64_t{-1}}) {
    const mpi_wire::Record r{7, 0, count, 0, 0};
    try {
      decode_observation(r);
      ADD_FAILURE() << "count " << count << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("a count of " + std::to_string(count)),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(ColumnMessages, RouteRoundTripsAfterItsCommandWordAndACutOneIsRefused) {
  const ColumnRoute sent{{1, 0, 1}, {0, 2}};
  const mpi_wire::Record r = encode(sent);
  // kRoute, 3 inputs, 2 completed groups.
  EXPECT_EQ(r, (mpi_wire::Record{mpi_wire::kRoute, 3, 1, 0, 1, 2, 0, 2}));
  mpi_wire::Reader in(r);
  EXPECT_EQ(in.next(), mpi_wire::kRoute);
  EXPECT_EQ(decode_route(in), sent);
  EXPECT_TRUE(in.done());
  for (std::size_t size = 2; size < r.size(); ++size) {
    const mpi_wire::Record cut(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(size));
    mpi_wire::Reader cut_in(cut);
    cut_in.next();
    EXPECT_THROW(decode_route(cut_in), std::runtime_error) << "cut to " << size << " words";
  }
}

TEST(ColumnMessages, WordsPastTheLastItemAreRefused) {
  mpi_wire::Record r = encode(five());
  r.push_back(0);
  EXPECT_THROW(decode_observation(r), std::runtime_error);
}

}  // namespace
}  // namespace l2
