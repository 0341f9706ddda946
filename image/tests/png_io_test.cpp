#include "image/png_io.hpp"

#include "image/picture_regions.hpp"
#include "test_folder.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace l2 {
namespace {

std::filesystem::path temp_dir() {
  return test_folder("l2_png_");
}

// The bytes of a file written by write_png, to be damaged.
std::string png_bytes(const RgbImage& image) {
  const auto path = temp_dir() / "written.png";
  write_png(path, image);
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

TEST(PngIo, RoundTripIsExact) {
  RgbImage img(17, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 17; ++x)
      img.set(x, y, {static_cast<std::uint8_t>(x * 15), static_cast<std::uint8_t>(y * 50), 77});
  const auto path = temp_dir() / "sub" / "round.png";
  write_png(path, img);
  EXPECT_EQ(read_png(path), img);
}

// libpng refuses a picture of no pixels: the error names the file written, or "in memory".
TEST(PngIo, AnEncodingThatFailsNamesTheFile) {
  const auto path = temp_dir() / "empty.png";
  try {
    write_png(path, RgbImage());
    ADD_FAILURE() << "an empty picture was written";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": cannot encode: ", 0), 0u) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  try {
    encode_png(RgbImage());
    ADD_FAILURE() << "an empty picture was encoded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("a PNG in memory: cannot encode: ", 0), 0u) << e.what();
  }
}

TEST(PngIo, MissingFileErrorNamesIt) {
  try {
    read_png("/nonexistent/frame-7.png");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/frame-7.png"), std::string::npos);
  }
}

TEST(PngIo, GarbageFileIsAnErrorNotACrash) {
  const auto path = temp_dir() / "garbage.png";
  std::ofstream(path) << "this is not a png";
  EXPECT_THROW(read_png(path), std::runtime_error);
}

// Two-pixel PNGs written by hand (zlib and CRC by Python's standard library), so that the
// reader is checked on files our writer does not make.
constexpr unsigned char kRgbaPng[] = {  // 2x1 RGBA: (10,20,30,40) (50,60,70,80)
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4,
    0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xe0,
    0x12, 0x91, 0xd3, 0x30, 0xb2, 0x71, 0x0b, 0x00, 0x00, 0x04, 0xb9, 0x01, 0x69, 0x03, 0x9d,
    0x56, 0x37, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
constexpr unsigned char kGreyPng[] = {  // 2x1 grey: 7, 200
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
    0x00, 0xd1, 0x49, 0x20, 0x56, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0x3f, 0x01, 0x00, 0x00, 0xd9, 0x00, 0xd0, 0xd7, 0xa6, 0x22, 0x3c,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

template <std::size_t N>
std::filesystem::path write_bytes(const std::string& name, const unsigned char (&bytes)[N]) {
  const auto path = temp_dir() / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes), N);
  return path;
}

TEST(PngIo, AlphaIsDroppedNotMultipliedIn) {
  const RgbImage img = read_png(write_bytes("rgba.png", kRgbaPng));
  ASSERT_EQ(img.width(), 2);
  ASSERT_EQ(img.height(), 1);
  EXPECT_EQ(img.at(0, 0), (Rgb{10, 20, 30}));
  EXPECT_EQ(img.at(1, 0), (Rgb{50, 60, 70}));
}

TEST(PngIo, GreyIsSpreadOverRgb) {
  const RgbImage img = read_png(write_bytes("grey.png", kGreyPng));
  ASSERT_EQ(img.width(), 2);
  EXPECT_EQ(img.at(0, 0), (Rgb{7, 7, 7}));
  EXPECT_EQ(img.at(1, 0), (Rgb{200, 200, 200}));
}

// The error read_png throws for `path`, or "no error".
std::string read_error(const std::filesystem::path& path) {
  try {
    read_png(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

// A scanned-out frame saved as grey or as JPEG was read (grey spread over RGB, JPEG decoded) and
// its headers reported as damaged. Other pictures may still be grey or JPEG.
TEST(PngIo, GreyPngsAreWrittenGrey) {
  const std::vector<std::uint8_t> grey = {0, 1, 2, 127, 128, 255};
  const std::string bytes = encode_grey_png(3, 2, grey);
  const std::vector<std::uint8_t> file(bytes.begin(), bytes.end());
  PictureSource source;
  const auto path = temp_dir() / "grey-map.png";
  std::ofstream(path, std::ios::binary) << bytes;
  const RgbImage read = read_png(path, &source);
  EXPECT_EQ(source.format, "png");
  EXPECT_EQ(source.colour_channels, 1);
  ASSERT_EQ(read.width(), 3);
  ASSERT_EQ(read.height(), 2);
  EXPECT_EQ(read.at(0, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(read.at(2, 0), (Rgb{2, 2, 2}));
  EXPECT_EQ(read.at(0, 1), (Rgb{127, 127, 127}));
  EXPECT_EQ(read.at(2, 1), (Rgb{255, 255, 255}));
  EXPECT_EQ(read_picture_bytes(file, "map"), read);
  EXPECT_THROW(encode_grey_png(3, 3, grey), std::invalid_argument);
}

TEST(PngIo, ScannedFrameRefusesGreyAndJpeg) {
  const auto grey = write_bytes("grey-frame.png", kGreyPng);
  EXPECT_EQ(read_png(grey).width(), 2);
  try {
    read_scanned_frame(grey);
    ADD_FAILURE() << "grey frame read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              grey.string() +
                  ": a grayscale picture (one colour channel) cannot hold strip headers: a "
                  "header is 48 bits in the R, G and B bytes of two pixels");
  }
  const auto jpeg = temp_dir() / "frame.jpg";
  write_png(jpeg, RgbImage(16, 8, {200, 10, 10}));  // OpenImageIO writes by the name: a JPEG
  const auto jpeg_named_png = temp_dir() / "jpeg-inside.png";
  std::filesystem::copy_file(jpeg, jpeg_named_png,
                             std::filesystem::copy_options::overwrite_existing);
  for (const auto& path : {jpeg, jpeg_named_png}) {
    PictureSource source;
    EXPECT_EQ(read_png(path, &source).width(), 16);
    EXPECT_EQ(source.format, "jpeg");
    EXPECT_TRUE(source.lossy);
    try {
      read_scanned_frame(path);
      ADD_FAILURE() << "JPEG frame read: " << path;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()),
                path.string() +
                    ": a JPEG picture cannot hold strip headers: the lossy compression changes "
                    "pixel bytes (save frames as PNG)");
    }
  }
  const auto rgb = temp_dir() / "rgb-frame.png";
  write_png(rgb, RgbImage(4, 2, {1, 2, 3}));
  EXPECT_EQ(read_scanned_frame(rgb), RgbImage(4, 2, {1, 2, 3}));
}

// A PNG header claiming 20000x20000 RGB pixels, followed by one tiny IDAT (Python's zlib).
constexpr unsigned char kHugeClaimPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x4e, 0x20, 0x00, 0x00, 0x4e, 0x20, 0x08, 0x02, 0x00, 0x00,
    0x00, 0x6c, 0x12, 0xd1, 0x6e, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x04, 0x00, 0x01, 0xf6, 0x17, 0x38,
    0x55, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

TEST(PngIo, ClaimedSizeOverTheLimitIsRefusedBeforeAllocating) {
  // Before the check this allocated 1.2 GB and failed later with "Not enough image data".
  const auto path = write_bytes("huge.png", kHugeClaimPng);
  EXPECT_EQ(read_error(path), path.string() +
                                  ": 20000x20000 pixels, larger than any picture read here "
                                  "(sides up to 16384)");
}

// A caller's own bound is asked before the reader's: a texture limit names the picture however
// large the size it claims.
TEST(PngIo, TheCallersSizeCheckIsAskedBeforeTheLimit) {
  const auto path = write_bytes("huge-claim.png", kHugeClaimPng);
  try {
    read_png(path, nullptr, [](int width, int height) {
      throw std::runtime_error("mine: " + std::to_string(width) + "x" + std::to_string(height));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "mine: 20000x20000");
  }
}

std::vector<std::uint8_t> bytes_of(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

// The error read_picture_bytes throws for `bytes`, or "no error".
std::string bytes_error(const std::vector<std::uint8_t>& bytes, const std::string& hint = {}) {
  try {
    read_picture_bytes(bytes, "model.glb: texture 0", hint);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

// A texture embedded in a model file is a picture file's bytes in memory: read as the file is,
// the format told by its first bytes (PNG, JPEG) or by the hint the model gives (TGA has no
// signature), and refused in one line naming what the caller says it is.
TEST(PngIo, PicturesInMemoryAreReadAsTheirFiles) {
  RgbImage img(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      img.set(x, y, {static_cast<std::uint8_t>(50 * x), static_cast<std::uint8_t>(100 * y), 9});
  for (const char* name : {"memory.png", "memory.jpg", "memory.tga", "memory.bmp"}) {
    const auto path = temp_dir() / name;
    write_png(path, img);
    const std::string hint = path.extension().string().substr(1);
    EXPECT_EQ(read_picture_bytes(bytes_of(path), "texture", hint), read_png(path)) << name;
  }
  const auto png = bytes_of(temp_dir() / "memory.png");
  EXPECT_EQ(read_picture_bytes(png, "texture"), img);
  const auto size_of = [&](int width, int height) {
    throw std::runtime_error("texture: " + std::to_string(width) + "x" + std::to_string(height));
  };
  EXPECT_THROW(read_picture_bytes(png, "texture", "", size_of), std::runtime_error);

  const std::string name = "model.glb: texture 0: cannot read: ";
  EXPECT_EQ(bytes_error({}), name + "no bytes");
  EXPECT_EQ(bytes_error({'n', 'o', 't', ' ', 'a', ' ', 'p', 'i', 'c'}),
            name + "not a picture of a format known here");
  EXPECT_EQ(bytes_error(std::vector<std::uint8_t>(png.begin(), png.end() - 20)),
            name + "the PNG file ends early (truncated)");
  const auto jpeg = bytes_of(temp_dir() / "memory.jpg");
  EXPECT_EQ(bytes_error(std::vector<std::uint8_t>(jpeg.begin(), jpeg.begin() + 40)).rfind(name, 0),
            0u);
}

// A DDS volume texture (24-bit RGB, `depth` slices) as DirectX lays out DDS_HEADER: 124 bytes
// after "DDS ", flags CAPS|HEIGHT|WIDTH|PIXELFORMAT|DEPTH, caps TEXTURE|COMPLEX, caps2 VOLUME
// (OpenImageIO refuses a volume without COMPLEX).
std::string dds_volume(std::uint32_t width, std::uint32_t height, std::uint32_t depth) {
  std::string bytes = "DDS ";
  const auto u32 = [&bytes](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>(v >> (8 * i)));
  };
  for (std::uint32_t v :
       {124u, 0x1u | 0x2u | 0x4u | 0x1000u | 0x800000u, height, width, width * 3, depth, 0u})
    u32(v);
  for (int i = 0; i < 11; ++i) u32(0);
  for (std::uint32_t v : {32u, 0x40u, 0u, 24u, 0xff0000u, 0xff00u, 0xffu, 0u}) u32(v);
  for (std::uint32_t v : {0x1000u | 0x8u, 0x200000u, 0u, 0u, 0u}) u32(v);
  bytes.append(std::size_t{width} * height * depth * 3, '\x7f');
  return bytes;
}

TEST(PngIo, VolumeImageNamedPngIsRefusedNotReadPastThePicture) {
  // OpenImageIO reads by content: this file's 4x4x8 pixels were read into a 4x4 picture, a heap
  // overflow (lightning2_emu route aborted with "malloc(): corrupted top size").
  const auto path = temp_dir() / "volume.png";
  std::ofstream(path, std::ios::binary) << dds_volume(4, 4, 8);
  EXPECT_EQ(read_error(path), path.string() + ": a volume (depth 8), not a picture");
}

// A damaged PNG: libpng printed "libpng error: ..." on stderr itself, and the error held
// OpenImageIO's lines ("PNG read error: ...", "PNG library error"). Now the reason alone.
TEST(PngIo, DamagedPngSaysWhyAndPrintsNothing) {
  const std::string bytes = png_bytes(RgbImage(64, 16, {1, 2, 3}));
  const auto truncated = temp_dir() / "truncated.png";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 20);
  std::string bad = bytes;
  bad[29] = static_cast<char>(bad[29] ^ 0xff);  // IHDR's CRC
  const auto bad_crc = temp_dir() / "bad-crc.png";
  std::ofstream(bad_crc, std::ios::binary) << bad;

  ::testing::internal::CaptureStderr();
  const std::string truncated_error = read_error(truncated);
  const std::string crc_error = read_error(bad_crc);
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(truncated_error,
            truncated.string() + ": cannot read: the PNG file ends early (truncated)");
  EXPECT_EQ(crc_error, bad_crc.string() + ": cannot read: a damaged PNG (IHDR: CRC error)");
  EXPECT_EQ(printed, "");
}

// A PNG whose line ends were converted in transfer (its signature's CR LF made LF): under a name
// another reader takes first (.dds, found by fuzz_picture_file), OpenImageIO's PNG reader, tried
// after it, printed libpng's line "libpng error: PNG file corrupted by ASCII conversion" on its
// own, and the image cache glued it to the end of our line. Both readers now take a file whose
// first four bytes say PNG as one: our line alone.
TEST(PngIo, APngWithConvertedLineEndsIsRefusedInOneLineWhateverItsName) {
  std::string bytes = png_bytes(RgbImage(8, 8, {1, 2, 3}));
  bytes.erase(4, 1);  // "\x89PNG\r\n\x1a\n": the CR gone
  for (const char* name : {"converted.png", "converted.dds", "converted.tga"}) {
    const auto path = temp_dir() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    const std::string want =
        path.string() + ": cannot read: a damaged PNG (PNG file corrupted by ASCII conversion)";
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(read_error(path), want);
    std::string regions_error;
    try {
      const PictureRegions regions(path);
    } catch (const std::runtime_error& e) {
      regions_error = e.what();
    }
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(regions_error, want);
    EXPECT_EQ(printed, "") << name;
  }
}

// A PPM that ends before its pixels: OpenImageIO fails it without a reason, and the message was
// "cannot read: " and nothing.
TEST(PngIo, ATruncatedPpmSaysWhy) {
  const auto path = temp_dir() / "short.ppm";
  std::ofstream(path, std::ios::binary) << "P6\n100 100\n255\n" << std::string(30, '\0');
  EXPECT_EQ(read_error(path),
            path.string() + ": cannot read: the PNM file is damaged or ends early");
}

// A damaged GIF named .png: OpenImageIO's PNG reader, chosen by the name, said "Not a PNG file".
// The reason is the GIF reader's, and the message says it is a GIF.
TEST(PngIo, ADamagedGifNamedPngIsCalledAGif) {
  const auto path = temp_dir() / "picture.png";
  // 4x4, no colour table anywhere.
  std::ofstream(path, std::ios::binary) << std::string(
      "GIF89a\x04\x00\x04\x00\x00\x00\x00,\x00\x00\x00\x00\x04\x00\x04\x00\x00"
      "\x02\x02\x44\x01\x00;",
      29);
  EXPECT_EQ(
      read_error(path),
      path.string() + ": cannot read: a GIF file: Neither local nor global colormap present.");
}

TEST(PngIo, MissingFileOrFolderSaysWhy) {
  EXPECT_EQ(read_error("/nonexistent/frame-7.png"),
            "/nonexistent/frame-7.png: cannot read: No such file or directory");
  const auto folder = temp_dir() / "folder.png";
  std::filesystem::create_directories(folder);
  EXPECT_EQ(read_error(folder), folder.string() + ": cannot read: a folder, not a file");
}

// Whether a shared library whose file name contains `name` is mapped into this process.
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    if (line.find(name) != std::string::npos) return true;
  }
  return false;
}

// OpenImageIO costs half a second of start-up; a process pays for it on its first picture of
// another format than PNG only (PNG is read and written with libpng, in memory too). A
// "threadsafe" death test runs its statement in a fresh process (this binary, executed again),
// where no picture has been read or written yet.
TEST(PngIoDeathTest, OpenImageIOIsLoadedOnTheFirstPictureThatIsNotAPngOnly) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto png = temp_dir() / "first.PNG";
  const auto bmp = temp_dir() / "first.bmp";
  EXPECT_EXIT(
      {
        const RgbImage picture(3, 2, {1, 2, 3});
        write_png(png, picture);
        const std::string bytes = encode_png(picture);
        const bool same =
            read_png(png) == picture &&
            read_picture_bytes({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()},
                               "a PNG in memory", "") == picture;
        if (mapped("libOpenImageIO")) {
          std::fputs("OpenImageIO loaded for a PNG\n", stderr);
          std::exit(1);
        }
        write_png(bmp, picture);
        if (!mapped("libOpenImageIO")) {
          std::fputs("OpenImageIO not loaded after writing a BMP\n", stderr);
          std::exit(2);
        }
        std::exit(same && read_png(bmp) == picture ? 0 : 3);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace l2
