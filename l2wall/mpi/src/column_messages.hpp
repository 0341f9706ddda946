// What the coordinator and the board columns say at every refresh, as types: the coordinator's
// tick (kCommand: the groups that swapped, the frame each pipeserver's link should carry, where
// its stamps are) and a column's observation (kObservation: what it found on its inputs and
// shows on its displays). Encoded as mpi_wire records; decoding refuses a record whose counts
// it cannot hold.
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

#include "l2wall/frame_stamp.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "swap_lock_check.hpp"

namespace l2 {

// A pipeserver's stamps this refresh: in the frame it delivers next (fb_x, fb_y), and on the
// displays for its last frame and the one before (display, dx, dy); a display shows one.
struct PipeserverStamps {
  StampSpot next, last, before;
  bool operator==(const PipeserverStamps&) const = default;
};

struct Tick {
  std::int64_t refresh = 0;
  std::vector<int> swapped_groups;       // indices of the swap-lock groups that swapped
  std::vector<std::uint64_t> sequences;  // by pipeserver: the frame its link carries now
  std::vector<PipeserverStamps> stamps;  // by pipeserver
  bool operator==(const Tick&) const = default;
};

// One input of the column as the router scanned it (the sequencer's FrameObservation).
struct InputSeen {
  int pipeserver = 0;
  bool present = false, idle = false, torn = false;
  int parity = 0;
  std::uint64_t displays_fed = 0;  // a bit per display id this column routes it to
  int stamp = -1;                  // the frame stamp of the frame taken in
  bool operator==(const InputSeen&) const = default;
};

// A pipeserver's stamps as this column's displays show them: of its last frame and of the one
// before, mpi_wire::kStampNotHere where the spot is on another column's display.
struct StampsShown {
  int pipeserver = 0;
  int last = mpi_wire::kStampNotHere, before = mpi_wire::kStampNotHere;
  bool operator==(const StampsShown&) const = default;
};

struct Observation {
  std::int64_t refresh = 0;
  std::vector<InputSeen> inputs;
  std::vector<StampsShown> stamps;
  std::vector<DisplayShown> displays;  // rank: not sent, the receiver knows who answered
  bool operator==(const Observation&) const = default;
};

// The record begins with the command word mpi_wire::kTick.
mpi_wire::Record encode(const Tick& tick);
// Reads what follows the command word; throws std::runtime_error for a record too short for
// its counts.
Tick decode_tick(mpi_wire::Reader& in);

mpi_wire::Record encode(const Observation& observation);
Observation decode_observation(const mpi_wire::Record& record);

}  // namespace l2
