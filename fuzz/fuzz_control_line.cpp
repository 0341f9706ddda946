// The balancing control channel's lines (balance/control_messages.hpp: TIMES with its batch
// footprints, LAYOUT, WANT, WINDOWS) as the coordinator and a pipeserver take them from their
// peer: a refusal is one line, and a line accepted encodes to one that decodes and encodes
// back to the same text.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "balance/control_messages.hpp"
#include "fuzz_check.hpp"

namespace {

using l2::fuzz::require;

template <typename Decode>
void round_trip(std::string_view line, Decode decode) {
  std::string once;
  try {
    once = l2::encode(decode(line));
  } catch (const l2::ControlError& e) {
    l2::fuzz::require_one_line(e.what(), "a refused control line is a one-line error");
    return;
  }
  std::string twice;
  try {
    twice = l2::encode(decode(once));
  } catch (const l2::ControlError&) {
    require(false, "a control line encoded from an accepted one is accepted");
  }
  require(twice == once, "an accepted control line encodes back to the same text");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  round_trip(line, [](std::string_view l) { return l2::decode_times(l); });
  round_trip(line, [](std::string_view l) { return l2::decode_layout(l); });
  round_trip(line, [](std::string_view l) { return l2::decode_want(l); });
  round_trip(line, [](std::string_view l) { return l2::decode_windows(l); });
  return 0;
}
