// Which formats are read, and by which reader (picture_formats.hpp): the signatures and list
// checked directly, then files whose name and content disagree through both readers (a whole
// read, read_png; a part at a time through the image cache, PictureRegions).
#include "image/picture_formats.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "image/picture_regions.hpp"
#include "image/png_io.hpp"
#include "test_folder.hpp"

namespace l2 {
namespace {

using namespace std::string_literals;
using png_codec::format_by_signature;

const std::string kReadHere =
    "(BMP, DDS, FITS, GIF, HDR, ICO, JPEG, OPENEXR, PNG, PNM, PSD, RLA, SGI, TARGA, TIFF, WEBP)";

TEST(PictureFormats, SignaturesNameTheirFormats) {
  EXPECT_EQ(format_by_signature("\x89PNG\r\n\x1a\n"), "png");
  EXPECT_EQ(format_by_signature("\xff\xd8\xff\xe0"), "jpeg");
  EXPECT_EQ(format_by_signature("II*\0"s), "tiff");
  EXPECT_EQ(format_by_signature("MM\0*"s), "tiff");
  EXPECT_EQ(format_by_signature("P6\n4 4\n255\n"), "pnm");
  EXPECT_EQ(format_by_signature("PF\n4 4\n-1\n"), "pnm");
  EXPECT_EQ(format_by_signature("#?RADIANCE\n"), "hdr");
  EXPECT_EQ(format_by_signature("SIMPLE  =                    T"), "fits");
  EXPECT_EQ(format_by_signature("\x01\xda\x00\x01"s), "sgi");
  EXPECT_EQ(format_by_signature("\0\0\1\0\1\0"s), "ico");
  EXPECT_EQ(format_by_signature("RIFF\x10\0\0\0WEBPVP8 "s), "webp");
  // Not read here, named all the same.
  EXPECT_EQ(format_by_signature("\xff\x4f\xff\x51\x00\x2f"s), "jpeg2000");
  EXPECT_EQ(format_by_signature("\0\0\0\x0cjP  \r\n\x87\n"s), "jpeg2000");
  EXPECT_EQ(format_by_signature("SDPX"), "dpx");
  EXPECT_EQ(format_by_signature("\0\0\0\x18"
                                "ftypheic"s),
            "heif");
  EXPECT_EQ(format_by_signature(std::string(128, '\0') + "DICM"), "dicom");
  // No signature: a Targa, an icon directory of no images, text, nothing.
  EXPECT_EQ(format_by_signature("\0\0\2\0\0\0\0\0"s), "");
  EXPECT_EQ(format_by_signature("\0\0\1\0\0\0"s), "");
  EXPECT_EQ(format_by_signature("not a picture"), "");
  EXPECT_EQ(format_by_signature(""), "");
}

TEST(PictureFormats, OnlyFormatsWhoseHeadersAreCheckedAreRead) {
  for (const char* format : {"png", "jpeg", "tiff", "targa", "openexr", "rla", "webp"})
    EXPECT_TRUE(png_codec::read_here(format)) << format;
  for (const char* format : {"jpeg2000", "dpx", "cineon", "heif", "raw", "ffmpeg", "iff", ""})
    EXPECT_FALSE(png_codec::read_here(format)) << format;
  EXPECT_EQ(png_codec::not_read_here("jpeg2000"),
            "cannot read: a JPEG2000 file, not a format read here " + kReadHere);
}

std::filesystem::path temp_dir() {
  return test_folder("l2_formats_");
}

std::filesystem::path file(const std::string& name, const std::string& bytes) {
  const auto path = temp_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The errors of both readers, which must agree.
std::string read_error(const std::filesystem::path& path) {
  std::string whole = "no error", regions = "no error";
  try {
    read_png(path);
  } catch (const std::runtime_error& e) {
    whole = e.what();
  }
  try {
    const PictureRegions picture(path);
  } catch (const std::runtime_error& e) {
    regions = e.what();
  }
  EXPECT_EQ(whole, regions) << path;
  return whole;
}

// OpenImageIO tried every reader it has on a file its name's reader could not open: a JPEG 2000
// codestream named .tga reached OpenJPEG, which no check bounds (1.1 GB for 177 bytes declaring
// 60000x60000). Now it is refused from its first bytes, whatever its name.
TEST(PictureFormats, AFormatNotReadHereIsRefusedWhateverItsName) {
  const std::string codestream = "\xff\x4f\xff\x51\x00\x2f"s + std::string(60, '\0');
  for (const char* name : {"picture.j2k", "picture.tga", "picture.png", "picture"}) {
    const auto path = file(name, codestream);
    EXPECT_EQ(
        read_error(path),
        path.string() + ": cannot read: a JPEG2000 file, not a format read here " + kReadHere);
  }
  // By name alone, without a signature: the name's reader is not one read here.
  const auto dpx = file("picture.dpx", std::string(100, 'x'));
  EXPECT_EQ(read_error(dpx),
            dpx.string() + ": cannot read: a DPX file, not a format read here " + kReadHere);
  // In memory, by the hint a model gives.
  try {
    read_picture_bytes(std::vector<std::uint8_t>(100, 'x'), "model.glb: texture 0", "jp2");
    ADD_FAILURE() << "read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "model.glb: texture 0: cannot read: a JPEG2000 file, not a "
              "format read here " +
                  kReadHere);
  }
}

// A file whose content is a format read here is read as that format whatever its name, by both
// readers (the image cache makes its readers of the content's format too); one without a
// signature, by its name's reader alone, which says why not.
TEST(PictureFormats, ContentDecidesTheReaderAndTheNameOnlyWithoutASignature) {
  RgbImage picture(6, 4, {200, 100, 50});
  const auto jpeg = temp_dir() / "written.jpg";
  write_png(jpeg, picture);
  std::ifstream in(jpeg, std::ios::binary);
  const auto named_png = file("jpeg.png", {std::istreambuf_iterator<char>(in), {}});
  EXPECT_EQ(read_png(named_png), read_png(jpeg));
  const PictureRegions regions(named_png);
  std::vector<std::uint8_t> row(6 * 3);
  regions.read_row(2, 0, 6, row.data());
  const RgbImage whole = read_png(jpeg);
  EXPECT_EQ(std::vector<std::uint8_t>(whole.row(2).begin(), whole.row(2).end()), row);

  const auto text = file("text.tga", "no picture here at all, just text");
  EXPECT_EQ(read_error(text).rfind(text.string() + ": cannot read: ", 0), 0u);
  EXPECT_EQ(read_error(text).find("TARGA"), std::string::npos) << "no signature named it";
  const auto unknown = file("text.xyz", "no picture here at all, just text");
  EXPECT_EQ(read_error(unknown),
            unknown.string() + ": cannot read: not a picture of a format known here");
}

}  // namespace
}  // namespace l2
