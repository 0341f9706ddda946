// Picture files made to hurt a reader that trusts them (issue 54): headers declaring more than
// their bytes hold, sides no wall uses, fields outside their format, PNGs cut short or damaged.
// Each is small; what it claims is not. Part of hostile_files.hpp, which includes it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pipeserver/hostile_png.hpp"

namespace l2::hostile {

// Pictures whose headers declare more than their bytes hold (issue 54). A binary PPM and a PFM of
// `width` x 1 with 300 bytes of samples.
inline std::string pnm_wide(long long width) {
  return "P6\n" + std::to_string(width) + " 1\n255\n" + std::string(300, '\0');
}
inline std::string pfm_wide(long long width) {
  return "PF\n" + std::to_string(width) + " 1\n-1.0\n" + std::string(300, '\0');
}

// The classic 35-byte GIF of one pixel, its logical screen declared `width` x `height`.
inline std::string gif_screen(int width, int height) {
  std::string g = "GIF89a";
  g += static_cast<char>(width & 0xFF);
  g += static_cast<char>(width >> 8);
  g += static_cast<char>(height & 0xFF);
  g += static_cast<char>(height >> 8);
  g += std::string(
      "\x80\x00\x00"
      "\x00\x00\x00\xff\xff\xff",
      9);                                                            // 2-colour table
  g += std::string("\x2c\x00\x00\x00\x00\x01\x00\x01\x00\x00", 10);  // a 1x1 image
  g += std::string("\x02\x02\x44\x01\x00\x3b", 6);                   // its LZW data, the trailer
  return g;
}

// An 8x8 grey baseline JPEG (FFmpeg's, bit-exact) whose frame header says `width` x `height`.
inline std::string jpeg_frame(int width, int height) {
  std::string j(
      "\xff\xd8\xff\xe0\x00\x10\x4a\x46\x49\x46\x00\x01\x02\x00\x00\x01\x00\x01\x00\x00\xff\xdb\x00"
      "\x43"
      "\x00\x08\x3e\x3e\x49\x3e\x49\x55\x55\x55\x55\x55\x55\x64\x5d\x64\x68\x68\x68\x64\x64\x64\x64"
      "\x68"
      "\x68\x68\x70\x70\x70\x83\x83\x83\x70\x70\x70\x68\x68\x70\x70\x7c\x7c\x83\x83\x8f\x93\x8f\x87"
      "\x87"
      "\x83\x87\x93\x93\x9b\x9b\x9b\xba\xba\xb2\xb2\xd9\xd9\xe0\xff\xff\xff\xff\xc4\x00\x4a\x00\x01"
      "\x00"
      "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x01\x01\x00\x00\x00\x00\x00\x00"
      "\x00"
      "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x10\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
      "\x00"
      "\x00\x00\x00\x11\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\xff\xc0"
      "\x00"
      "\x11\x08\x00\x08\x00\x08\x03\x01\x22\x00\x02\x11\x00\x03\x11\x00\xff\xda\x00\x0c\x03\x01\x00"
      "\x02"
      "\x11\x03\x11\x00\x3f\x00\x00\x0f\xff\xd9",
      202);
  for (std::size_t at = 2; at + 9 < j.size();) {
    const auto marker = static_cast<unsigned char>(j[at + 1]);
    if (marker == 0xC0) {
      j[at + 5] = static_cast<char>(height >> 8);
      j[at + 6] = static_cast<char>(height & 0xFF);
      j[at + 7] = static_cast<char>(width >> 8);
      j[at + 8] = static_cast<char>(width & 0xFF);
      break;
    }
    at += 2 + (static_cast<unsigned char>(j[at + 2]) << 8 | static_cast<unsigned char>(j[at + 3]));
  }
  return j;
}

// A DDS of 8x8 RGB pixels whose header declares `levels` mipmap levels.
inline std::string dds_levels(std::uint32_t levels) {
  const auto u32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 24)};
  };
  std::string d = "DDS " + u32(124) + u32(0x2100F) + u32(8) + u32(8) + u32(24) + u32(0) +
                  u32(levels) + std::string(44, '\0');
  d += u32(32) + u32(0x40) + u32(0) + u32(24) + u32(0xFF0000) + u32(0xFF00) + u32(0xFF) + u32(0);
  d += u32(0x401008) + std::string(16, '\0');
  return d + std::string(8 * 8 * 3 * 2, '\x80');
}

// --- More formats whose headers OpenImageIO believes (issue 54) -------------------------------

inline std::string le16(std::uint16_t v) {
  return bytes_of(v);
}
inline std::string le32(std::uint32_t v) {
  return bytes_of(v);
}

// A little-endian TIFF of RGB bytes: each directory declares `width` x `height` pixels of
// `samples` samples of `bits` bits, uncompressed, as one strip (or, with `tile` > 0, tiles of
// `tile` x `tile`, or `tile` x `tile_length` when that is given) whose `data` follows;
// `directories` such directories, chained, then those of `more` (a pyramid's levels).
struct Tiff {
  std::uint32_t width = 8, height = 8, samples = 3, bits = 8, tile = 0;
  int directories = 1;
  std::string data = std::string(300, '\0');
  std::optional<std::uint32_t> tile_length = std::nullopt;
  std::vector<Tiff> more = {};
};
// One directory of `t` at the end of `out`, naming the next when `last` is false.
inline void tiff_directory(std::string& out, const Tiff& t, bool last) {
  // Tags in ascending order: (tag, type, value), SHORT = 3, LONG = 4; a SHORT sits in the
  // first two bytes of its value field.
  std::vector<std::pair<std::uint16_t, std::uint32_t>> tags = {
      {256, t.width}, {257, t.height}, {258, t.bits}, {259, 1}, {262, t.samples >= 3 ? 2u : 1u}};
  const bool tiled = t.tile > 0;
  if (!tiled) tags.push_back({273, 0});
  tags.push_back({277, t.samples});
  if (!tiled) tags.insert(tags.end(), {{278, t.height}, {279, 0}});
  if (tiled)
    tags.insert(tags.end(),
                {{322, t.tile}, {323, t.tile_length.value_or(t.tile)}, {324, 0}, {325, 0}});
  const auto at = static_cast<std::uint32_t>(out.size());
  const auto data_at = static_cast<std::uint32_t>(at + 2 + 12 * tags.size() + 4);
  const auto next = static_cast<std::uint32_t>(data_at + t.data.size());
  out += le16(static_cast<std::uint16_t>(tags.size()));
  for (auto [tag, value] : tags) {
    const bool is_short = tag == 258 || tag == 259 || tag == 262 || tag == 277;
    if (tag == 273 || tag == 324) value = data_at;
    if (tag == 279 || tag == 325) value = static_cast<std::uint32_t>(t.data.size());
    out += le16(tag) + le16(is_short ? 3 : 4) + le32(1) +
           (is_short ? le16(static_cast<std::uint16_t>(value)) + le16(0) : le32(value));
  }
  out += le32(last ? 0 : next) + t.data;
}
inline std::string tiff(const Tiff& t) {
  std::string out = "II*" + std::string(1, '\0') + le32(8);
  for (int d = 0; d < t.directories; ++d)
    tiff_directory(out, t, d + 1 == t.directories && t.more.empty());
  for (std::size_t m = 0; m < t.more.size(); ++m)
    tiff_directory(out, t.more[m], m + 1 == t.more.size());
  return out;
}

// A 24-bit BMP declaring `width` x `height` (negative: top-down) with 300 bytes of pixels.
inline std::string bmp(std::int32_t width, std::int32_t height) {
  const std::string pixels(300, '\0');
  const std::string info = le32(40) + bytes_of(width) + bytes_of(height) + le16(1) + le16(24) +
                           le32(0) + le32(0) + le32(2835) + le32(2835) + le32(0) + le32(0);
  return "BM" + le32(static_cast<std::uint32_t>(14 + info.size() + pixels.size())) + le32(0) +
         le32(14 + 40) + info + pixels;
}

// A Radiance HDR declaring `width` x `height` with 300 bytes of pixels.
inline std::string hdr(long long width, long long height) {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " +
         std::to_string(width) + "\n" + std::string(300, '\0');
}

// A FITS file of 8-bit samples declaring `width` x `height`, with one 2880-byte block of them.
inline std::string fits(long long width, long long height) {
  const auto card = [](const std::string& key, const std::string& value) {
    std::string c = key;
    c.resize(8, ' ');
    c += "= ";
    c += std::string(20 - std::min<std::size_t>(20, value.size()), ' ') + value;
    c.resize(80, ' ');
    return c;
  };
  std::string h = card("SIMPLE", "T") + card("BITPIX", "8") + card("NAXIS", "2") +
                  card("NAXIS1", std::to_string(width)) + card("NAXIS2", std::to_string(height));
  h += "END";
  h.resize(2880, ' ');
  return h + std::string(2880, '\0');
}

// An ICO of one icon, the PNG `png` (its directory entry says 256x256, as icons larger than 255
// do).
inline std::string ico(const std::string& png) {
  return le16(0) + le16(1) + le16(1) + std::string(4, '\0') + le16(1) + le16(32) +
         le32(static_cast<std::uint32_t>(png.size())) + le32(6 + 16) + png;
}

// An OpenEXR file (magic number, version 2) whose first header attribute declares `size` bytes
// of value and holds 3; OpenEXR allocated the size declared before reading it.
inline std::string exr_attribute(std::uint32_t size) {
  return std::string("\x76\x2f\x31\x01", 4) + le32(2) + std::string("junk\0opaque\0", 12) +
         le32(size) + "abc";
}

// An OpenEXR file of `channels` half-float channels named A, B, ..., of `compression`
// (OpenEXR's code: 0 none, 4 PIZ), its data window `width` x `height`, then 4096 bytes:
// OpenEXR allocated the buffer of a chunk as it opened the file (fuzz_picture_file's 26 channels
// a million pixels wide in PIZ's chunks of 32 lines: 1.6 GB).
inline std::string exr_window(std::uint32_t width, std::uint32_t height, int channels,
                              unsigned char compression) {
  const auto attribute = [](const std::string& name, const std::string& type,
                            const std::string& value) {
    return name + '\0' + type + '\0' + le32(static_cast<std::uint32_t>(value.size())) + value;
  };
  std::string list;
  for (int c = 0; c < channels; ++c) {
    list += std::string(1, static_cast<char>('A' + c)) + '\0' + le32(1) + std::string(4, '\0') +
            le32(1) + le32(1);
  }
  list += '\0';
  const std::string window = le32(0) + le32(0) + le32(width - 1) + le32(height - 1);
  const std::string one = le32(0) + le32(0) + le32(0) + le32(0);
  return std::string("\x76\x2f\x31\x01", 4) + le32(2) + attribute("channels", "chlist", list) +
         attribute("compression", "compression", std::string(1, static_cast<char>(compression))) +
         attribute("dataWindow", "box2i", window) + attribute("displayWindow", "box2i", one) +
         attribute("lineOrder", "lineOrder", std::string(1, '\0')) +
         attribute("pixelAspectRatio", "float", le32(0x3f800000)) +
         attribute("screenWindowCenter", "v2f", std::string(8, '\0')) +
         attribute("screenWindowWidth", "float", le32(0x3f800000)) + std::string(1, '\0') +
         std::string(4096, '\0');
}

// An ICO of one `side` x `side` bitmap image whose header says `header_size` bytes and `bits` a
// pixel, its directory entry `colours`, its palette and rows as its bits take. OpenImageIO's ICO
// reader trusts both: fuzz_picture_file's header (2304 header bytes, 1 bit a pixel, 16,778,241
// wide, 2048 planes: the seed heap-1bit.ico) corrupted the heap in `strip_headers dump`, and so
// did a well-formed 12x12 icon of 4 bits (its mask written past the reader's buffer).
inline std::string ico_bitmap(std::uint32_t header_size, std::uint16_t bits, std::uint8_t side = 4,
                              std::uint8_t colours = 0) {
  std::string dib = le32(header_size) + le32(side) + le32(2u * side) + le16(1) + le16(bits);
  dib.resize(40, '\0');
  const std::size_t palette = bits <= 8 ? 4u << bits : 0;
  dib += std::string(palette + ((side * bits + 31u) / 32 + (side + 31u) / 32) * 4 * side, '\0');
  return le16(0) + le16(1) + le16(1) + std::string{char(side), char(side), char(colours), 0} +
         le16(1) + le16(32) + le32(static_cast<std::uint32_t>(dib.size())) + le32(6 + 16) + dib;
}

// An SGI image's header (big-endian: magic 474, `storage`, `bytes_per_channel`, 3 dimensions,
// 4x4 pixels of 3 channels) and its planes at one byte a sample: a `bytes_per_channel` of 0
// crashed the reader as it read a row.
inline std::string sgi(unsigned char storage, unsigned char bytes_per_channel) {
  std::string h("\x01\xDA", 2);
  h += static_cast<char>(storage);
  h += static_cast<char>(bytes_per_channel);
  h += std::string("\x00\x03\x00\x04\x00\x04\x00\x03", 8);
  h.resize(512, '\0');
  return h + std::string(48, '\x40');
}

// fuzz_picture_file's SGI of RLE storage and dimension 1 (one row of one channel, 256 wide)
// whose tables, sized by its ysize x zsize of 43283 x 0, are empty: the reader looked up the
// first row's offset in them and crashed (SIGSEGV).
inline std::string sgi_empty_tables() {
  return std::string("\x01\xDA\x01\x01\x00\x01\x01\x00\xA9\x13\x00\x00", 12) +
         std::string(133, '\x96');
}

// dds_levels(1) with its green bit mask zero: OpenImageIO's reader shifted it for ever.
inline std::string dds_no_green() {
  std::string d = dds_levels(1);
  d.replace(96, 4, std::string(4, '\0'));
  return d;
}

// A TIFF of 24x2049 grey bytes in strips whose RowsPerStrip says 855,640,105 rows
// (fuzz_picture_file's): OpenImageIO sized its read buffer by it, not by the height, and asked
// for 20 GB. For the picture scene: a whole read refuses a grey picture anyway (no strip
// headers fit in one channel).
inline std::string tiff_tall_strips() {
  std::string t = "II*" + std::string(1, '\0') + le32(8) + le16(8);
  const auto entry = [&t](std::uint16_t tag, std::uint16_t type, std::uint32_t value) {
    t += le16(tag) + le16(type) + le32(1) +
         (type == 3 ? le16(static_cast<std::uint16_t>(value)) + le16(0) : le32(value));
  };
  entry(256, 4, 24);         // width
  entry(257, 4, 2049);       // height
  entry(258, 3, 8);          // bits a sample
  entry(262, 3, 1);          // grey, black at 0
  entry(273, 4, 200);        // the strip's offset
  entry(277, 3, 1);          // samples a pixel
  entry(278, 4, 855640105);  // rows a strip
  entry(279, 4, 300);        // the strip's bytes
  t += le32(0);
  t.resize(200, '\0');
  return t + std::string(300, '\x40');
}

// dds_levels(1) flagged alpha alone (fuzz_picture_file's flags 0xFFFDFFC2, RGB among them),
// its alpha mask zero: OpenImageIO's reader spread the alpha bits over a byte in steps of zero,
// for good.
inline std::string dds_alpha_alone() {
  std::string d = dds_levels(1);
  d.replace(80, 4, std::string("\xC2\xFF\xFD\xFF", 4));
  return d;
}

// fits(9, 4) declaring three axes: its depth, the missing third, is 0, on which the image cache
// aborted (an assertion; found by fuzz_picture_file).
inline std::string fits_missing_axis() {
  std::string f = fits(9, 4);
  f.replace(f.find("NAXIS   =                    2"), 30, "NAXIS   =                    3");
  return f;
}
// A JPEG 2000 codestream (OpenJPEG's, 64x64 RGB: `oiiotool --pattern constant:color=0.2,0.4,0.6
// 64x64 3 -d uint8 -o small.j2k`) whose SIZ marker declares `side` x `side` pixels in one tile.
// No check bounds OpenJPEG, and OpenImageIO tried its reader on any file its name's reader could
// not open: 177 bytes named .tga of 60000x60000 took 1.1 GB, of 1000000x1000000 hung
// `strip_headers dump`. The format is not read here.
inline std::string jpeg2000(std::uint32_t side) {
  std::string j(
      "\xff\x4f\xff\x51\x00\x2f\x00\x00\x00\x00\x00\x40\x00\x00\x00\x40\x00\x00\x00\x00"
      "\x00\x00\x00\x00\x00\x00\x00\x40\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\x00\x00"
      "\x00\x03\x07\x01\x01\x07\x01\x01\x07\x01\x01\xff\x52\x00\x0c\x00\x00\x00\x01\x00"
      "\x05\x04\x04\x00\x01\xff\x5c\x00\x13\x40\x40\x48\x48\x50\x48\x48\x50\x48\x48\x50"
      "\x48\x48\x50\x48\x48\x50\xff\x64\x00\x25\x00\x01\x43\x72\x65\x61\x74\x65\x64\x20"
      "\x62\x79\x20\x4f\x70\x65\x6e\x4a\x50\x45\x47\x20\x76\x65\x72\x73\x69\x6f\x6e\x20"
      "\x32\x2e\x35\x2e\x30\xff\x90\x00\x0a\x00\x00\x00\x00\x00\x32\x00\x01\xff\x93\xcf"
      "\xb4\x14\x08\x8f\x9e\x9d\xbf\xc3\xe7\x06\x08\x84\xdc\xc3\xe7\x08\x01\xcd\x60\x3f"
      "\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\x80\xff\xd9",
      177);
  for (const std::size_t at : {8, 12, 24, 28}) j.replace(at, 4, big_endian(side));
  return j;
}

// A 4x4 Wavefront RLA file (no signature: read as RLA by its name) of 3 colour channels of
// `type` (0 bytes, 1 words, other types as bytes) and `bits`, and `aux` auxiliary byte channels
// of `aux_bits`, each row of each channel one run of 0x40 a byte of its samples. 0 auxiliary
// bits hung OpenImageIO's reader and type 3 aborted it (found by fuzz_picture_file); 20-bit
// words had it write past its row buffer.
inline std::string rla(int type, int bits, int aux, int aux_bits) {
  const auto be16 = [](int v) {
    return big_endian(static_cast<std::uint32_t>(v) << 16).substr(0, 2);
  };
  std::string h = be16(0) + be16(3) + be16(0) + be16(3) + be16(0) + be16(3) + be16(0) + be16(3) +
                  be16(1) + be16(type) + be16(3) + be16(0) + be16(aux) + be16(-2);
  h.resize(740, '\0');
  h.replace(658, 2, be16(bits)).replace(666, 2, be16(aux_bits));
  std::string row;
  for (int c = 0; c < 3 + aux; ++c) {
    const int spans = c < 3 && type == 1 ? 2 : 1;  // one a byte of a sample
    row += be16(2 * spans) + (spans == 2 ? "\x03\x40\x03\x40" : "\x03\x40");
  }
  for (std::uint32_t y = 0; y < 4; ++y) h += big_endian(740 + 16 + y * std::uint32_t(row.size()));
  return h + row + row + row + row;
}

}  // namespace l2::hostile
