// TUIO datagrams as a tracker sends them, encoded by liblo (lo_bundle_serialise), for tests:
// one bundle per frame of "source", "alive", a "set" per finger and "fseq".
#pragma once

#include <lo/lo_lowlevel.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace l2::testing_support {

struct TuioFinger {
  int id = 0;
  float x = 0, y = 0;
};

inline std::vector<std::uint8_t> serialised(lo_bundle b) {
  std::size_t size = 0;
  void* data = lo_bundle_serialise(b, nullptr, &size);
  std::vector<std::uint8_t> bytes(static_cast<std::uint8_t*>(data),
                                  static_cast<std::uint8_t*>(data) + size);
  std::free(data);
  return bytes;
}

// One frame: `fingers` down (alive and set), numbered `fseq`.
inline std::vector<std::uint8_t> tuio_frame(int fseq, const std::vector<TuioFinger>& fingers) {
  const lo_timetag immediate{0U, 1U};  // LO_TT_IMMEDIATE, without its C compound literal
  lo_bundle b = lo_bundle_new(immediate);
  lo_message source = lo_message_new();
  lo_message_add_string(source, "source");
  lo_message_add_string(source, "test@127.0.0.1");
  lo_bundle_add_message(b, "/tuio/2Dcur", source);
  lo_message alive = lo_message_new();
  lo_message_add_string(alive, "alive");
  for (const TuioFinger& f : fingers) lo_message_add_int32(alive, f.id);
  lo_bundle_add_message(b, "/tuio/2Dcur", alive);
  for (const TuioFinger& f : fingers) {
    lo_message set = lo_message_new();
    lo_message_add_string(set, "set");
    lo_message_add_int32(set, f.id);
    for (const float v : {f.x, f.y, 0.0f, 0.0f, 0.0f}) lo_message_add_float(set, v);
    lo_bundle_add_message(b, "/tuio/2Dcur", set);
  }
  lo_message seq = lo_message_new();
  lo_message_add_string(seq, "fseq");
  lo_message_add_int32(seq, fseq);
  lo_bundle_add_message(b, "/tuio/2Dcur", seq);
  std::vector<std::uint8_t> bytes = serialised(b);
  lo_bundle_free_recursive(b);
  return bytes;
}

}  // namespace l2::testing_support
