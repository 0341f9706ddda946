// What the coordinator and the board columns say at every refresh (l2wall/column_records.hpp)
// as mpi_wire records: the coordinator's tick and route (kCommand) and a column's observation
// (kObservation). Decoding refuses a record whose counts it cannot hold.
//
// Example:
//   Tick tick;
//   tick.refresh = 7;
//   tick.swapped_groups = {0};
//   tick.sequences = {8, 8};  // and tick.stamps, one HostStamps per pipeserver
//   mpi_wire::send(encode(tick), column_rank, mpi_wire::kCommand);
//   // on the column, after reading the command word kTick:
//   const Tick got = decode_tick(reader);
#pragma once

#include <cstdint>
#include <vector>

#include "l2wall/column_records.hpp"
#include "mpi_link/mpi_wire.hpp"

namespace l2 {

// The record begins with the command word mpi_wire::kTick.
mpi_wire::Record encode(const Tick& tick);
// Reads what follows the command word; throws std::runtime_error for a record too short for
// its counts.
Tick decode_tick(mpi_wire::Reader& in);

mpi_wire::Record encode(const Observation& observation);
Observation decode_observation(const mpi_wire::Record& record);

// The record begins with the command word mpi_wire::kRoute.
mpi_wire::Record encode(const ColumnRoute& route);
// Reads what follows the command word.
ColumnRoute decode_route(mpi_wire::Reader& in);

}  // namespace l2
