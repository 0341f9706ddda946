// The PNG frame reader (read_scanned_frame: libpng through the image codec module) on arbitrary
// files: a picture within the size limit, or one error line naming the file. Only files that
// start with the PNG signature are read; the others go to OpenImageIO's many readers, which
// are not this project's code. Files declaring more than kMaxArea pixels are skipped so that
// executions stay fast; the refusal of sides over kMaxPictureSide is still reached (a 20000x1
// picture is small).
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "fuzz_check.hpp"
#include "image/png_io.hpp"

namespace {

using l2::fuzz::require;

constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr std::uint64_t kMaxArea = 1u << 20;

std::uint32_t big_endian(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

// The memory file the inputs are written to, read back through its /proc/self/fd path.
int input_file() {
  static const int fd = ::memfd_create("fuzz-png", 0);
  require(fd >= 0, "memfd_create works");
  return fd;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < sizeof kSignature || std::memcmp(data, kSignature, sizeof kSignature) != 0) return 0;
  // IHDR's width and height sit at bytes 16..23 of a well-formed file.
  if (size >= 24 && std::uint64_t{big_endian(data + 16)} * big_endian(data + 20) > kMaxArea &&
      big_endian(data + 16) <= l2::kMaxPictureSide &&
      big_endian(data + 20) <= l2::kMaxPictureSide) {
    return 0;
  }
  const int fd = input_file();
  require(::ftruncate(fd, 0) == 0 && ::pwrite(fd, data, size, 0) == static_cast<ssize_t>(size),
          "the input is written to the memory file");
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  try {
    const l2::RgbImage frame = l2::read_scanned_frame(path);
    require(frame.width() >= 1 && frame.width() <= l2::kMaxPictureSide && frame.height() >= 1 &&
                frame.height() <= l2::kMaxPictureSide,
            "a picture read has sides 1..kMaxPictureSide");
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    l2::fuzz::require_one_line(message, "a picture error is one line");
    require(message.rfind(path + ": ", 0) == 0, "a picture error names the file first");
  }
  return 0;
}
