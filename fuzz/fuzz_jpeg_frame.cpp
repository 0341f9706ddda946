// A shared screen's frame as the control page's server takes it (image/jpeg_frame.hpp), on
// arbitrary bytes: decoded within small limits chosen by the input's first byte, or refused.
// Never a crash, a hang or an allocation past the limits (ASan), every refusal one line, and a
// picture decoded is of a size within the limits.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "image/jpeg_frame.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // Limits small enough for the fuzzer's pace, from 1x1 to 256x256.
  const int side = 1 + data[0];
  const l2::JpegFrameLimits limits{side, side, std::size_t{1} << 20};
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  const l2::Result<l2::RgbImage> frame = l2::decode_jpeg_frame(bytes, limits);
  if (!frame.ok()) {
    l2::fuzz::require_one_line(frame.reason(), "a refused frame is one line");
    return 0;
  }
  l2::fuzz::require(frame->width() >= 1 && frame->width() <= side && frame->height() >= 1 &&
                        frame->height() <= side,
                    "a decoded frame is within the limits");
  return 0;
}
