#include "image/tiff_header.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <set>
#include <string>
#include <string_view>

namespace l2::png_codec {

namespace {

// Numbers as the file's byte order stores them.
struct Order {
  bool big_endian = false;
  std::uint64_t at(std::string_view b, std::size_t offset, int n) const {
    if (offset + n > b.size()) return 0;
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) {
      const std::uint64_t byte = static_cast<unsigned char>(b[offset + i]);
      v |= big_endian ? byte << (8 * (n - 1 - i)) : byte << (8 * i);
    }
    return v;
  }
};

// Classic TIFF: 2-byte entry counts, 12-byte entries, 4-byte offsets; BigTIFF: 8, 20 and 8.
struct Layout {
  Order order;
  bool big = false;
  int count_bytes() const { return big ? 8 : 2; }
  int entry_bytes() const { return big ? 20 : 12; }
  int offset_bytes() const { return big ? 8 : 4; }
};

enum Tag : std::uint16_t {
  kWidth = 256,
  kLength = 257,
  kBitsPerSample = 258,
  kCompression = 259,
  kSamplesPerPixel = 277,
  kRowsPerStrip = 278,
  kTileWidth = 322,
  kTileLength = 323,
};

// What libtiff's reader and OpenImageIO call the compression scheme; the number itself for one
// neither names here, which max_expansion bounds by its most generous figure.
std::string compression_name(std::uint64_t scheme) {
  switch (scheme) {
    case 1:
      return "none";
    case 5:
      return "lzw";
    case 7:
      return "jpeg";
    case 8:
    case 32946:
      return "zip";
    case 32773:
      return "packbits";
    default:
      return "compression " + std::to_string(scheme);
  }
}

// Every compression scheme libtiff has a number for (tiff.h's COMPRESSION_*), decoder or not.
// A scheme outside them no reader decodes; OpenImageIO still sized a buffer for such a file by
// its RowsPerStrip (45 GB asked by a 273-byte file) before saying so.
bool scheme_libtiff_knows(std::uint64_t scheme) {
  static constexpr std::uint64_t kKnown[] = {1,     2,     3,     4,     5,     6,     7,     8,
                                             32766, 32771, 32773, 32809, 32895, 32896, 32897, 32898,
                                             32908, 32909, 32946, 32947, 34661, 34676, 34677, 34712,
                                             34887, 34925, 50000, 50001, 50002};
  return std::find(std::begin(kKnown), std::end(kKnown), scheme) != std::end(kKnown);
}

long long side(std::uint64_t v) {
  return static_cast<long long>(std::min<std::uint64_t>(v, LLONG_MAX));
}

// The bytes of one value of an entry's type, for the integer types libtiff reads a number from
// (BYTE, SBYTE, SHORT, SSHORT, LONG, SLONG, LONG8, SLONG8); 0 for others, whose entries it
// skips.
int value_bytes(std::uint64_t type) {
  switch (type) {
    case 1:
    case 6:
      return 1;
    case 3:
    case 8:
      return 2;
    case 4:
    case 9:
      return 4;
    case 16:
    case 17:
      return 8;
    default:
      return 0;
  }
}

// One entry's first value: inline when its values fit the entry, else read where it points.
std::uint64_t first_value(const Layout& l, std::string_view entry, const ReadAt& read) {
  const std::uint64_t count = l.order.at(entry, 4, l.big ? 8 : 4);
  const std::size_t value_at = l.big ? 12 : 8;
  const int size = value_bytes(l.order.at(entry, 2, 2));
  if (count == 0) return 0;
  if (count * size <= static_cast<std::uint64_t>(l.offset_bytes()))
    return l.order.at(entry, value_at, size);
  return l.order.at(read(l.order.at(entry, value_at, l.offset_bytes()), size), 0, size);
}

// A directory's entries as Declared (at most the 65535 entries libtiff reads), its compression
// scheme's number (`scheme`: 1, none, where it gives none) and its RowsPerStrip (0 where it gives
// none).
Declared directory_facts(const Layout& l, std::uint64_t at, std::uint64_t entries,
                         const ReadAt& read, std::uint64_t& scheme, std::uint64_t& rows_per_strip) {
  Declared d;
  scheme = 1;
  rows_per_strip = 0;
  d.format = "tiff";
  d.compression = "none";
  d.channels = 1;
  std::uint64_t bits = 1;
  const std::string b = read(at + l.count_bytes(), entries * l.entry_bytes());
  // A tag given twice counts at its larger value (the checks bound the most a reader could
  // take); an entry of a type no number is read from is skipped, as libtiff skips it (a second
  // width entry of type 0 pointing past the file had hidden the first: fuzz_picture_file).
  for (std::size_t e = 0; e + l.entry_bytes() <= b.size(); e += l.entry_bytes()) {
    const std::string_view entry(b.data() + e, l.entry_bytes());
    if (value_bytes(l.order.at(entry, 2, 2)) == 0) continue;
    const std::uint64_t value = first_value(l, entry, read);
    switch (l.order.at(entry, 0, 2)) {
      case kWidth:
        d.width = std::max(d.width, side(value));
        break;
      case kLength:
        d.height = std::max(d.height, side(value));
        break;
      case kBitsPerSample:
        bits = std::max(bits, value);
        break;
      case kCompression:
        d.compression = compression_name(value);
        scheme = value;
        break;
      case kRowsPerStrip:
        rows_per_strip = std::max(rows_per_strip, value);
        break;
      case kSamplesPerPixel:
        d.channels =
            std::max(d.channels, static_cast<int>(std::min<std::uint64_t>(value, INT_MAX)));
        break;
      case kTileWidth:
        d.tile_width = std::max(d.tile_width, side(value));
        break;
      case kTileLength:
        d.tile_height = std::max(d.tile_height, side(value));
        break;
      default:
        break;
    }
  }
  // Samples below a byte are read as bytes; wider ones as whole bytes (more than 8 is no format).
  d.bytes_per_channel = static_cast<int>(std::min<std::uint64_t>((bits + 7) / 8, 9));
  if (d.bytes_per_channel < 1) d.bytes_per_channel = 1;
  return d;
}

// OpenImageIO reads a TIFF stored in strips in chunks of a whole number of strips, its buffer
// sized by the RowsPerStrip the file gives (read as an int; none, or one past an int's range,
// counts as 64), not by the picture's height: a 157-byte file of 24x2049 pixels whose strips
// say 855,640,105 rows asked for 20 GB (found by fuzz_picture_file). Writers give at most the
// height, or 2^32 - 1 for "one strip"; a strip holding more than kMaxWholeMegabytes is refused.
Status check_strips(const Declared& d, std::uint64_t rows_per_strip) {
  if (d.tile_width > 0 || rows_per_strip == 0 || rows_per_strip > INT_MAX) return {};
  const double bytes =
      double(rows_per_strip) * double(d.width) * d.channels * std::max(d.bytes_per_channel, 1);
  if (bytes <= kMaxWholeMegabytes * (1 << 20)) return {};
  return Failure{"strips of " + std::to_string(rows_per_strip) + " rows of " +
                 std::to_string(d.width) + " pixels (" +
                 std::to_string(static_cast<long long>(std::ceil(bytes / (1 << 20)))) +
                 " MiB each), more than the " + std::to_string(int(kMaxWholeMegabytes)) +
                 " MiB its reader may hold at once; save it with fewer rows a strip"};
}

}  // namespace

TiffFacts tiff_facts(const ReadAt& read, std::uintmax_t file_size) {
  TiffFacts facts;
  const std::string header = read(0, 16);
  Layout l;
  if (header.substr(0, 2) == "MM") {
    l.order.big_endian = true;
  } else if (header.substr(0, 2) != "II") {
    return facts;
  }
  const std::uint64_t magic = l.order.at(header, 2, 2);
  if (magic != 42 && magic != 43) return facts;
  l.big = magic == 43;
  facts.tiff = true;
  std::uint64_t at = l.big ? l.order.at(header, 8, 8) : l.order.at(header, 4, 4);
  std::set<std::uint64_t> seen;
  while (at != 0 && at < file_size && seen.insert(at).second &&
         facts.directories <= kMaxTiffDirectories) {
    const std::uint64_t entries = l.order.at(read(at, l.count_bytes()), 0, l.count_bytes());
    const std::uint64_t end = at + l.count_bytes() + entries * l.entry_bytes();
    // The next directory's offset may be missing at the file's end: libtiff reads the entries
    // and takes none (fuzz_picture_file's 118-byte TIFF, its RowsPerStrip asking 1.2 GB).
    if (entries == 0 || entries > 65535 || end > file_size) break;
    std::uint64_t scheme = 1, rows_per_strip = 0;
    facts.each.push_back(directory_facts(l, at, entries, read, scheme, rows_per_strip));
    facts.schemes.push_back(scheme);
    facts.rows_per_strip.push_back(rows_per_strip);
    if (facts.directories == 0) facts.first = facts.each.front();
    ++facts.directories;
    at = end + l.offset_bytes() <= file_size
             ? l.order.at(read(end, l.offset_bytes()), 0, l.offset_bytes())
             : 0;
  }
  return facts;
}

Status check_tiff(const ReadAt& read, std::uintmax_t file_size) {
  const TiffFacts facts = tiff_facts(read, file_size);
  if (!facts.tiff) return {};
  if (facts.directories > kMaxTiffDirectories) {
    return Failure{"cannot read: a TIFF of more than " + std::to_string(kMaxTiffDirectories) +
                   " directories (pages or levels), more than its reader opens in time; the "
                   "first is shown: save it alone"};
  }
  for (std::size_t i = 0; i < facts.each.size(); ++i) {
    const Declared& d = facts.each[i];
    const std::string which =
        i == 0 ? "" : "directory " + std::to_string(i + 1) + " (a level or page): ";
    if ((d.tile_width == 0) != (d.tile_height == 0)) {
      return Failure{"cannot read: " + which + "declares tiles of " + std::to_string(d.tile_width) +
                     "x" + std::to_string(d.tile_height) + " pixels"};
    }
    if (!scheme_libtiff_knows(facts.schemes[i])) {
      return Failure{"cannot read: " + which + "a TIFF compressed by scheme " +
                     std::to_string(facts.schemes[i]) + ", which no TIFF reader knows"};
    }
    if (d.width == 0 || d.height == 0) continue;
    const Status s = check_declared(d, file_size);
    if (!s.ok()) {
      const std::string prefix = "cannot read: ";
      return Failure{prefix + which +
                     s.reason().substr(s.reason().rfind(prefix, 0) == 0 ? prefix.size() : 0)};
    }
    // After what the picture declares as a whole: its strips are how it is read.
    if (const Status strips = check_strips(d, facts.rows_per_strip[i]); !strips.ok()) {
      return Failure{"cannot read: " + which + strips.reason()};
    }
  }
  return {};
}

}  // namespace l2::png_codec
