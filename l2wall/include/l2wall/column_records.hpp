// What the DVI path and the board columns say to each other at every refresh, as types: the
// path's tick (the groups that swapped, the frame each pipeserver's link should carry, where its
// stamps are), a column's observation (what it found on its inputs and shows on its displays),
// and the route (which inputs to write, which groups complete). In one process they are passed
// as they are (LocalColumns); over MPI they are encoded as records (mpi/src/column_messages.hpp).
//
// Example: one refresh of a wall with one group, pipeserver 0 delivering frame 7
//   Tick tick{.refresh = 41, .swapped_groups = {0}, .sequences = {8}, .stamps = {spots}};
//   // a column answers: Observation{.refresh = 41, .inputs = {{.pipeserver = 0, ...,
//   //                                                          .stamp = 7}}, ...}
//   ColumnRoute route{.route = {1}, .completed_groups = {0}};
#pragma once

#include <cstdint>
#include <vector>

#include "l2wall/frame_stamp.hpp"

namespace l2 {

// In a column's observation: a pipeserver's stamp that lands on another column's display, not
// read there.
inline constexpr int kStampNotHere = -1;
// In the tick, for a pipeserver lost (--survive-host-loss): its input carries no signal from now
// on.
inline constexpr std::uint64_t kNoSignal = ~std::uint64_t{0};

// A pipeserver's stamps this refresh: in the frame it delivers next (fb_x, fb_y), and on the
// displays for its last frame and the one before (display, dx, dy); a display shows one.
struct PipeserverStamps {
  StampSpot next, last, before;
  bool operator==(const PipeserverStamps&) const = default;
};

struct Tick {
  std::int64_t refresh = 0;
  std::vector<int> swapped_groups;       // indices of the swap-lock groups that swap now
  std::vector<std::uint64_t> sequences;  // by pipeserver: the frame its link carries now
  std::vector<PipeserverStamps> stamps;  // by pipeserver
  bool operator==(const Tick&) const = default;
};

// One input of a column as its router scanned it (the sequencer's FrameObservation, with the
// displays it fed rather than the groups: the path knows the groups).
struct InputSeen {
  int pipeserver = 0;
  bool present = false, idle = false, torn = false;
  int parity = 0;
  std::uint64_t displays_fed = 0;  // a bit per display id this column routes it to
  int stamp = -1;                  // the frame stamp of the frame taken in
  bool operator==(const InputSeen&) const = default;
};

// A pipeserver's stamps as a column's displays show them: of its last frame and of the one
// before, kStampNotHere where the spot is on another column's display.
struct StampsShown {
  int pipeserver = 0;
  int last = kStampNotHere, before = kStampNotHere;
  bool operator==(const StampsShown&) const = default;
};

// The frame a display shows, for the swap-lock check (swap_lock_check.hpp).
struct DisplayShown {
  int display = 0;  // id
  int frame = -1;   // the frame stamp it shows; -1: no frame yet (background only)
  int rank = 0;     // the column rank that holds it (0 in one process)
  // The oldest frame stamp among the pipeservers' strips routed into the picture it shows:
  // `frame` when every part of it is of one frame (a packed stereo display's halves, both eyes,
  // packed_stereo_record.hpp); -1: none.
  int oldest = -1;
  bool operator==(const DisplayShown&) const = default;
};

struct Observation {
  std::int64_t refresh = 0;
  // The mesh of the column (tilelayout/several_meshes.hpp): its inputs' displays_fed are bits of
  // that mesh's display ids.
  int mesh = 0;
  std::vector<InputSeen> inputs;
  std::vector<StampsShown> stamps;
  std::vector<DisplayShown> displays;  // rank: not sent, the receiver knows who answered
  bool operator==(const Observation&) const = default;
};

// The sequencer's decision as the columns need it: which mesh inputs to write (1: write), and
// which groups (indices) complete their frame now, to swap at the next refresh.
struct ColumnRoute {
  std::vector<std::uint8_t> route;
  std::vector<int> completed_groups;
  bool operator==(const ColumnRoute&) const = default;
};

}  // namespace l2
