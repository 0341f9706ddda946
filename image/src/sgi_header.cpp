#include "image/sgi_header.hpp"

#include <climits>
#include <string>

#include "byte_fields.hpp"

namespace l2::png_codec {

namespace {

constexpr std::uint64_t kHeaderBytes = 512;

Failure refused(const std::string& what) {
  return Failure{"cannot read: an SGI image " + what};
}

// Whether a row's runs, as the reader decodes them (a count byte, or with 2 bytes a channel a
// count word, its high bit saying "copy the next count samples", else "repeat the next sample"),
// stay within the row's `bytes` and write at most `width` samples.
bool runs_fit(const std::string& bytes, unsigned bpc, std::uint64_t width) {
  std::uint64_t i = 0, written = 0;
  const std::uint64_t n = bytes.size();
  while (i < n) {
    if (i + bpc > n) return false;  // the count itself
    const unsigned value = bpc == 1 ? static_cast<unsigned char>(bytes[i]) : be(bytes, i, 2);
    i += bpc;
    const unsigned count = value & 0x7F;
    if (count == 0) break;
    const std::uint64_t read = value & 0x80 ? std::uint64_t{count} * bpc : bpc;
    if (i + read > n || written + count > width) return false;
    i += read;
    written += count;
  }
  return true;
}

}  // namespace

Status check_sgi_rle(const ReadAt& read, std::uintmax_t file_size) {
  const std::string h = read(0, 12);
  if (h.size() < 12 || be(h, 0, 2) != 474 || h[2] != 1) return {};
  const unsigned bpc = static_cast<unsigned char>(h[3]), dimension = be(h, 4, 2);
  const std::uint64_t width = be(h, 6, 2), ysize = be(h, 8, 2), zsize = be(h, 10, 2);
  if (bpc != 1 && bpc != 2) return {};  // check_header refuses it
  const std::uint64_t rows = dimension == 1 ? 1 : ysize, channels = dimension == 3 ? zsize : 1;
  const std::uint64_t entries = ysize * zsize;
  if (rows * channels > entries) {
    return refused("of " + std::to_string(rows) + " row(s) of " + std::to_string(channels) +
                   " channel(s) whose RLE tables hold " + std::to_string(entries) + " (" +
                   std::to_string(ysize) + " x " + std::to_string(zsize) + ")");
  }
  if (kHeaderBytes + 8 * entries > file_size) {
    return refused("declaring RLE tables of " + std::to_string(entries) + " rows, " +
                   std::to_string(8 * entries) + " bytes, past the end of its " +
                   std::to_string(file_size) + " bytes");
  }
  const std::string starts = read(kHeaderBytes, 4 * rows * channels);
  const std::string lengths = read(kHeaderBytes + 4 * entries, 4 * rows * channels);
  if (starts.size() < 4 * rows * channels || lengths.size() < 4 * rows * channels) return {};
  for (std::uint64_t row = 0; row < rows * channels; ++row) {
    const std::uint64_t start = be(starts, 4 * row, 4), length = be(lengths, 4 * row, 4);
    if (start > INT_MAX || length > INT_MAX || start + length > file_size) {
      return refused("whose row " + std::to_string(row) + " is " + std::to_string(length) +
                     " bytes at " + std::to_string(start) + ", past the end of its " +
                     std::to_string(file_size) + " bytes");
    }
    const std::string bytes = read(start, length);
    if (bytes.size() < length) return {};  // a short read: the reader finds it
    if (!runs_fit(bytes, bpc, width)) {
      return refused("whose row " + std::to_string(row) + " runs past its " +
                     std::to_string(length) + " bytes or its width of " + std::to_string(width));
    }
  }
  return {};
}

}  // namespace l2::png_codec
