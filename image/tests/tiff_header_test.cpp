// A TIFF's directories as tiff_header.hpp walks them, on bytes laid out here by hand: both byte
// orders, BigTIFF, values stored beside their entry, a chain that loops, one past the limit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/tiff_header.hpp"

namespace l2::png_codec {
namespace {

// Numbers of `n` bytes in the file's byte order.
std::string num(std::uint64_t v, int n, bool big_endian) {
  std::string out(static_cast<std::size_t>(n), '\0');
  for (int i = 0; i < n; ++i) out[big_endian ? n - 1 - i : i] = static_cast<char>(v >> (8 * i));
  return out;
}

struct Entry {
  std::uint16_t tag, type;
  std::uint64_t count, value;
};

// A directory of `entries` at the end of `file`, linked to `next`.
void directory(std::string& file, const std::vector<Entry>& entries, std::uint64_t next,
               bool big_endian, bool bigtiff) {
  const int offset = bigtiff ? 8 : 4;
  file += num(entries.size(), bigtiff ? 8 : 2, big_endian);
  for (const Entry& e : entries) {
    file +=
        num(e.tag, 2, big_endian) + num(e.type, 2, big_endian) + num(e.count, offset, big_endian);
    // A value that fits sits in the field's first bytes (left-justified), an offset fills it.
    const int size = e.type == 3 ? 2 : e.type == 4 ? 4 : 8;
    const bool inline_value = e.count * size <= static_cast<std::uint64_t>(offset);
    file += inline_value ? num(e.value, size, big_endian) + std::string(offset - size, '\0')
                         : num(e.value, offset, big_endian);
  }
  file += num(next, offset, big_endian);
}

ReadAt reader(const std::string& file) {
  return [file](std::uint64_t at, std::size_t n) {
    return at >= file.size() ? std::string() : file.substr(at, n);
  };
}

TEST(TiffHeader, BothByteOrdersAndBigTiffDeclareTheirFirstDirectory) {
  for (const bool big_endian : {false, true}) {
    for (const bool bigtiff : {false, true}) {
      std::string f = big_endian ? "MM" : "II";
      f += bigtiff ? num(43, 2, big_endian) + num(8, 2, big_endian) + num(0, 2, big_endian) +
                         num(16, 8, big_endian)
                   : num(42, 2, big_endian) + num(8, 4, big_endian);
      directory(f,
                {{256, 4, 1, 3000},
                 {257, 3, 1, 2000},
                 {258, 3, 1, 16},
                 {259, 3, 1, 5},
                 {277, 3, 1, 4},
                 {322, 3, 1, 512},
                 {323, 3, 1, 256}},
                0, big_endian, bigtiff);
      const TiffFacts facts = tiff_facts(reader(f), f.size());
      ASSERT_TRUE(facts.tiff);
      EXPECT_EQ(facts.directories, 1);
      EXPECT_EQ(facts.first.width, 3000);
      EXPECT_EQ(facts.first.height, 2000);
      EXPECT_EQ(facts.first.channels, 4);
      EXPECT_EQ(facts.first.bytes_per_channel, 2);
      EXPECT_EQ(facts.first.compression, "lzw");
      EXPECT_EQ(facts.first.tile_width, 512);
      EXPECT_EQ(facts.first.tile_height, 256);
    }
  }
}

TEST(TiffHeader, BitsPerSampleStoredBesideTheEntry) {
  // Three SHORTs (6 bytes) do not fit a classic entry's 4: they sit at offset 100.
  std::string f = "II" + num(42, 2, false) + num(8, 4, false);
  directory(f, {{256, 3, 1, 8}, {257, 3, 1, 8}, {258, 3, 3, 100}, {277, 3, 1, 3}}, 0, false, false);
  f.resize(100, '\0');
  f += num(32, 2, false) + num(32, 2, false) + num(32, 2, false);
  const TiffFacts facts = tiff_facts(reader(f), f.size());
  EXPECT_EQ(facts.first.bytes_per_channel, 4);
  EXPECT_EQ(facts.first.compression, "none");  // no Compression tag: stored as it is
}

TEST(TiffHeader, ChainsAreCountedToTheLimitAndLoopsEnd) {
  // Directories of one entry (18 bytes each) one after another from offset 8.
  const auto chain = [](int n, std::uint64_t last_next) {
    std::string f = "II" + num(42, 2, false) + num(8, 4, false);
    for (int i = 0; i < n; ++i) {
      directory(f, {{256, 3, 1, 1}}, i + 1 < n ? f.size() + 18 : last_next, false, false);
    }
    return f;
  };
  const std::string pages = chain(kMaxTiffDirectories, 0);
  EXPECT_EQ(tiff_facts(reader(pages), pages.size()).directories, kMaxTiffDirectories);
  const std::string more = chain(kMaxTiffDirectories + 1, 0);
  EXPECT_EQ(check_tiff(reader(more), more.size()).reason(),
            "cannot read: a TIFF of more than 256 directories (pages or levels), more than its "
            "reader opens in time; the first is shown: save it alone");
  // The third directory names the first again: three, as libtiff reads them.
  const std::string loop = chain(3, 8);
  EXPECT_EQ(tiff_facts(reader(loop), loop.size()).directories, 3);
  // One pointing past the file's end is the reader's to refuse.
  const std::string past = chain(2, 1 << 30);
  EXPECT_EQ(tiff_facts(reader(past), past.size()).directories, 2);
}

// A pyramid of three directories, 4096x4096 in tiles of 64 and two levels after it, whose
// second level declares `level`: each directory is checked as the first is.
std::string pyramid(const std::vector<Entry>& level) {
  std::string f = "II" + num(42, 2, false) + num(8, 4, false);
  const std::vector<Entry> first = {
      {256, 4, 1, 4096}, {257, 4, 1, 4096}, {277, 3, 1, 3}, {322, 3, 1, 64}, {323, 3, 1, 64}};
  const std::vector<Entry> half = {
      {256, 4, 1, 2048}, {257, 4, 1, 2048}, {277, 3, 1, 3}, {322, 3, 1, 64}, {323, 3, 1, 64}};
  directory(f, first, f.size() + 2 + 12 * first.size() + 4, false, false);
  directory(f, half, f.size() + 2 + 12 * half.size() + 4, false, false);
  directory(f, level, 0, false, false);
  f.resize(4096 * 4096 * 3 / 2, '\0');  // zip holds its pixels in these bytes
  return f;
}

TEST(TiffHeader, EveryLevelOfAPyramidIsChecked) {
  const std::string fine = pyramid(
      {{256, 4, 1, 1024}, {257, 4, 1, 1024}, {277, 3, 1, 3}, {322, 3, 1, 64}, {323, 3, 1, 64}});
  const TiffFacts facts = tiff_facts(reader(fine), fine.size());
  ASSERT_EQ(facts.each.size(), 3u);
  EXPECT_EQ(facts.each[2].width, 1024);
  EXPECT_TRUE(check_tiff(reader(fine), fine.size()).ok());

  const std::string huge_tiles = pyramid({{256, 4, 1, 1024},
                                          {257, 4, 1, 1024},
                                          {277, 3, 1, 3},
                                          {322, 4, 1, 65536},
                                          {323, 4, 1, 65536}});
  EXPECT_EQ(check_tiff(reader(huge_tiles), huge_tiles.size()).reason(),
            "cannot read: directory 3 (a level or page): tiles of 65536x65536 pixels (12288 MiB "
            "each), more than the 64 MiB a reader holds");

  const std::string zero_tiles = pyramid(
      {{256, 4, 1, 1024}, {257, 4, 1, 1024}, {277, 3, 1, 3}, {322, 3, 1, 64}, {323, 3, 1, 0}});
  EXPECT_EQ(check_tiff(reader(zero_tiles), zero_tiles.size()).reason(),
            "cannot read: directory 3 (a level or page): declares tiles of 64x0 pixels");

  const std::string past = pyramid({{256, 4, 1, 1000000},
                                    {257, 4, 1, 1000000},
                                    {277, 3, 1, 3},
                                    {322, 3, 1, 64},
                                    {323, 3, 1, 64}});
  const std::string why = check_tiff(reader(past), past.size()).reason();
  EXPECT_EQ(why.rfind("cannot read: directory 3 (a level or page): declares 1000000x1000000 "
                      "pixels",
                      0),
            0u)
      << why;
}

// A compression scheme no TIFF reader knows (768, found by fuzz_picture_file): its reader
// sized a buffer by the file's RowsPerStrip, 45 GB for this 8x8 picture, before saying it could
// not decode it. Refused from the header; a scheme libtiff knows is the reader's to judge.
TEST(TiffHeader, ASchemeNoReaderKnowsIsRefused) {
  for (const std::uint64_t scheme : {768, 50002}) {
    std::string f = "II" + num(42, 2, false) + num(8, 4, false);
    directory(f,
              {{256, 4, 1, 8},
               {257, 4, 1, 8},
               {258, 3, 1, 8},
               {259, 3, 1, scheme},
               {277, 3, 1, 3},
               {278, 4, 1, 8}},
              0, false, false);
    const Status s = check_tiff(reader(f), f.size());
    if (scheme == 768) {
      EXPECT_EQ(s.reason(),
                "cannot read: a TIFF compressed by scheme 768, which no TIFF reader knows");
    } else {
      EXPECT_TRUE(s.ok()) << s.reason();  // JPEG XL: libtiff has its number
    }
  }
}

// OpenImageIO sizes its buffer by RowsPerStrip, not the height: fuzz_picture_file's 24x2049
// picture of one sample a pixel in strips of 855,640,105 rows asked for 20 GB. 855,640,105 x 24
// bytes is 19585 MiB, rounded up; 8 rows of 8 RGB pixels a strip, or the "one strip" value
// 2^32 - 1 (which the reader takes as none), are fine, and 22,369,621 rows of 8 RGB pixels are
// 511.99 MiB.
TEST(TiffHeader, StripsLargerThanTheReaderHoldsAreRefused) {
  const auto strips = [](std::uint64_t width, std::uint64_t samples, std::uint64_t rows) {
    std::string f = "II" + num(42, 2, false) + num(8, 4, false);
    directory(f,
              {{256, 4, 1, width},
               {257, 4, 1, 2049},
               {259, 3, 1, 3},
               {277, 3, 1, samples},
               {278, 4, 1, rows}},
              0, false, false);
    return check_tiff(reader(f), 100000000);
  };
  EXPECT_EQ(strips(24, 1, 855640105).reason(),
            "cannot read: strips of 855640105 rows of 24 pixels (19585 MiB each), more than the "
            "512 MiB its reader may hold at once; save it with fewer rows a strip");
  EXPECT_TRUE(strips(8, 3, 8).ok());
  EXPECT_TRUE(strips(8, 3, 4294967295u).ok());
  EXPECT_TRUE(strips(8, 3, 22369621).ok());
  EXPECT_FALSE(strips(8, 3, 22369622).ok());
}

// A directory whose next offset the file's end cuts off is still read, as libtiff reads it
// (fuzz_picture_file's 118-byte TIFF: its strips of 50,331,689 rows had the reader ask 1.2 GB).
TEST(TiffHeader, ADirectoryWithoutItsNextOffsetIsChecked) {
  std::string f = "II" + num(42, 2, false) + num(8, 4, false);
  directory(f, {{256, 4, 1, 24}, {257, 4, 1, 2049}, {278, 4, 1, 50331689}}, 0, false, false);
  f.resize(f.size() - 4);  // no next directory's offset
  EXPECT_EQ(check_tiff(reader(f), f.size()).reason(),
            "cannot read: strips of 50331689 rows of 24 pixels (1153 MiB each), more than the "
            "512 MiB its reader may hold at once; save it with fewer rows a strip");
  f.resize(f.size() - 1);  // its last entry cut short: libtiff cannot read the directory
  EXPECT_TRUE(check_tiff(reader(f), f.size()).ok());
}

// A second width entry of type 0 (no number libtiff reads), its 524,544 values past the file,
// had the walk take the width as 0 and skip the directory's checks (fuzz_picture_file); a tag
// given twice counts at its larger value.
TEST(TiffHeader, EntriesOfNoNumberTypeAreSkippedAndRepeatsCountAtTheirLargest) {
  const auto check = [](std::uint16_t second_type, std::uint64_t count,
                        std::uint64_t second_width) {
    std::string f = "II" + num(42, 2, false) + num(8, 4, false);
    directory(f,
              {{256, 4, 1, 24},
               {257, 4, 1, 2049},
               {259, 3, 1, 3},
               {256, second_type, count, second_width},
               {278, 4, 1, 855640105}},
              0, false, false);
    return check_tiff(reader(f), 100000000).reason();
  };
  const std::string strips =
      "cannot read: strips of 855640105 rows of 24 pixels (19585 MiB "
      "each), more than the 512 MiB its reader may hold at once; save it "
      "with fewer rows a strip";
  EXPECT_EQ(check(0, 524544, 512), strips);
  EXPECT_EQ(check(4, 524544, 99999999), strips);  // a valid type, its values past the file: none
  EXPECT_EQ(check(3, 1, 48).find("strips of 855640105 rows of 48 pixels"), 13u) << check(3, 1, 48);
}

TEST(TiffHeader, OtherBytesAreNoTiff) {
  for (const std::string& f : {std::string("P6\n8 8\n255\n"), std::string("II*"), std::string()}) {
    EXPECT_FALSE(tiff_facts(reader(f), f.size()).tiff) << f;
    EXPECT_TRUE(check_tiff(reader(f), f.size()).ok()) << f;
  }
}

}  // namespace
}  // namespace l2::png_codec
