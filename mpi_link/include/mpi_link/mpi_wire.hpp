// The messages of an MPI run, one tag each (docs/mpi-design.md), and the few calls every role
// makes with them: blocking sends of small integer records, a receive that keeps watching while
// it waits, and large messages waited for without busy-polling.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace l2::mpi_wire {

enum Tag : int {
  kFrame = 1,        // pipeserver -> column: 8-byte sequence number, then the RGB frame
  kNotice = 2,       // pipeserver -> coordinator: the sequence number just published
  kReady = 3,        // coordinator -> pipeserver: a 17-byte READY line (docs/ready-protocol.md)
  kSync = 4,         // pipeserver -> coordinator: a 17-byte SYNC? line
  kCommand = 5,      // coordinator -> column: a Command record
  kObservation = 6,  // column -> coordinator: what it saw in a refresh
  kPicture = 7,      // column -> coordinator: one display's front buffer
  kDone = 8,         // pipeserver -> coordinator: bytes of frames it sent, its report complete
  kTile = 9,         // pipeserver -> column: a TileMessage header, then the tile's pixels
  kComposed = 10,    // column -> coordinator: the frame its compositing completed
  kSwapped = 11,     // coordinator -> pipeserver: frames up to this one are composed everywhere
  kControl = 12,     // pipeserver <-> coordinator: a balanced run's TIMES and LAYOUT lines
  kWindows = 13,     // pipeserver <-> coordinator: a vnc run's WANT, DESKTOP and RECT lines
  kLost = 14,        // coordinator -> column: a pipeserver whose rank is gone, survived
};

// The viz path over MPI: a tile (kind 1, to the column owning its display)
// or the end of a pipeserver's frame (kind 2, to every column), one tag, so they keep order.
struct TileMessage {
  std::int32_t kind = 0;
  std::uint32_t frame = 0;
  std::uint32_t display = 0;
  std::int32_t dx = 0, dy = 0;
  std::uint32_t w = 0, h = 0;
  std::uint32_t tiles = 0;  // kind 2: how many tiles the pipeserver sent for the frame
  // Kind 1: how the tile is composited (viz::TileKind, spec §7) and a KEY tile's key colour;
  // a DEPTH tile's rows are its colour, then its depth, as in TILE_EXT.
  std::uint32_t how = 0;
  std::uint32_t key = 0;
};
// Kind 3: a tile as what changed since its last frame (tile_delta.hpp), the encoded message
// after the header.
inline constexpr std::int32_t kTileKind = 1, kFrameDoneKind = 2, kTileDeltaKind = 3;

// What the coordinator asks of a column (the first word of a record).
enum Command : std::int64_t { kTick = 1, kRoute = 2, kFetch = 3, kEnd = 4, kFetchComposed = 5 };

using Record = std::vector<std::int64_t>;

// Throws std::runtime_error naming the call and the peer when MPI reports an error.
void send(const Record& record, int to, int tag);
// Whether a message of `tag` from `from` is waiting (MPI_ANY_SOURCE allowed); its size in
// bytes.
std::optional<int> waiting(int from, int tag);
Record receive(int from, int tag);
// One message of `bytes` (a picture, a tile) sent or received whole, waiting as the run's other
// waits do. MPI_Send and MPI_Recv busy-poll until a large message has crossed, yield or not:
// on a slow or lossy link that is most of a frame, spent on a core the ranks working beside it
// need. These wait as MPI would for a millisecond (a fast link has carried a picture by then),
// then look every 100 microseconds. Throw as `send` does.
void send_bytes(std::span<const std::uint8_t> bytes, int to, int tag);
void receive_bytes(std::span<std::uint8_t> into, int from, int tag);
// Waits for a record, calling `watch` (which may throw) about every millisecond meanwhile.
Record receive_watched(int from, int tag, const std::function<void()>& watch);

// A cursor over a received record; throws std::runtime_error past its end.
class Reader {
 public:
  explicit Reader(const Record& r) : r_(r) {}
  std::int64_t next();
  int next_int() { return static_cast<int>(next()); }
  // A count of items of `words` words each that follow: throws when the record cannot hold
  // them, so that a corrupt count never sizes an allocation.
  std::size_t count(std::size_t words);
  bool done() const { return at_ == r_.size(); }

 private:
  const Record& r_;
  std::size_t at_ = 0;
};

}  // namespace l2::mpi_wire
