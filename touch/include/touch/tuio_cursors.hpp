// TUIO 1.1 cursors (/tuio/2Dcur) from OSC messages to committed frames. A tracker sends each of
// its frames as "alive" (the session ids of every finger down), a "set" per finger that moved
// (id, x, y in 0..1, then velocity and acceleration, not used here), and "fseq" (the frame's
// number), which commits what came before it. It owns the cursors as last committed and what
// the current frame has said so far; it keeps no time and does no I/O.
//
// Input is never trusted: a message that breaks a rule below is dropped whole and counted, and
// so is an fseq older than the last committed (a late bundle: its messages are dropped with it):
//   - alive: at most kMaxTouchCursors ids, each an int32 0 or more;
//   - set: an int32 id 0 or more, x and y finite and within 0..1, at most 5 numbers after the id;
//   - fseq: one int32.
// Messages to other addresses (/tuio/2Dobj, /tuio/2Dblb) and "source" are not cursors: ignored.
//
//   TuioCursors cursors;
//   for (const OscMessage& m : *decode_osc(datagram))
//     if (std::optional<CursorFrame> f = cursors.take(m)) gestures.take(*f, windows);
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "touch/osc_packet.hpp"

namespace l2 {

// More fingers than a wall's touch frame reports; what bounds every list kept here.
inline constexpr int kMaxTouchCursors = 32;

struct Cursor {
  std::int32_t id = 0;
  double x = 0, y = 0;  // 0..1 across and down the canvas
  friend bool operator==(const Cursor&, const Cursor&) = default;
};

// The fingers down in one committed frame, by id; a finger alive but never set is not in it.
struct CursorFrame {
  std::int32_t fseq = 0;
  std::vector<Cursor> cursors;
};

class TuioCursors {
 public:
  // One message of a datagram; the frame it commits when it is an fseq that commits one.
  std::optional<CursorFrame> take(const OscMessage& m);
  // Messages dropped by the rules above, late frames' included.
  long dropped_messages() const { return dropped_; }

 private:
  bool take_alive(const OscMessage& m);
  bool take_set(const OscMessage& m);
  std::optional<CursorFrame> take_fseq(const OscMessage& m);
  std::vector<Cursor> next_cursors() const;
  void forget_pending();

  std::vector<Cursor> committed_;                        // by id
  std::optional<std::vector<std::int32_t>> next_alive_;  // this frame's alive, once said
  std::vector<Cursor> next_set_;                         // this frame's sets, one per id
  std::optional<std::int64_t> last_fseq_;
  long dropped_ = 0;
};

}  // namespace l2
