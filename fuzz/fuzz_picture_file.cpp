// Picture files of every format through both readers, as the programs meet them, after the
// checks of what a header declares (image/declared_size.hpp, image/tiff_header.hpp): read_png
// (a whole picture, within a caller's bound on the sides: strip_headers dump, lightning2_emu
// route, textures) and PictureRegions (a part at a time through the image cache: the picture
// scene). The first byte picks the file's extension, which OpenImageIO tries first (a Targa has
// no signature); the rest is the file. A picture, or one error line naming the file; never a
// crash, a hang, or memory past the limits scripts/fuzz.sh gives (-malloc_limit_mb, a bound on
// any one allocation, and -rss_limit_mb). Rows are read only from pictures of up to kMaxArea
// pixels, so that executions stay fast.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_check.hpp"
#include "image/picture_regions.hpp"
#include "image/png_io.hpp"

namespace {

using l2::fuzz::require;

constexpr long long kMaxArea = 1 << 16;
constexpr int kMaxSide = 256;

const char* const kExtensions[] = {"png", "jpg", "tif", "bmp", "ppm", "pfm", "hdr", "fits",
                                   "ico", "gif", "tga", "dds", "exr", "sgi", "psd", "rla"};

void require_error(const std::string& message, const std::string& path, const char* what) {
  l2::fuzz::require_one_line(message, what);
  require(message.rfind(path + ": ", 0) == 0, "a picture error names the file first");
}

void read_whole(const std::string& path) {
  try {
    const l2::RgbImage picture = l2::read_png(path, nullptr, [](int width, int height) {
      if (width > kMaxSide || height > kMaxSide) throw std::runtime_error("too large to fuzz");
    });
    require(picture.width() >= 1 && picture.width() <= kMaxSide && picture.height() >= 1 &&
                picture.height() <= kMaxSide,
            "a whole picture read has sides within the caller's bound");
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()) != "too large to fuzz") {
      require_error(e.what(), path, "a whole read's error is one line");
    }
  }
}

void read_regions(const std::string& path) {
  try {
    const l2::PictureRegions picture(path);
    require(picture.width() >= 1 && picture.height() >= 1, "an opened picture has pixels");
    if (static_cast<long long>(picture.width()) * picture.height() > kMaxArea) return;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(picture.width()) * 3);
    for (const int y : {0, picture.height() / 2, picture.height() - 1}) {
      picture.read_row(y, 0, picture.width(), rgb.data());
    }
    // Each MIP level a zoomed-out view reads: its sides halve the level's before it, so its
    // rows fit the first's.
    for (int level = 1; level < picture.levels(); ++level) {
      require(picture.width(level) >= 1 && picture.width(level) <= picture.width(level - 1) &&
                  picture.height(level) >= 1 && picture.height(level) <= picture.height(level - 1),
              "a level's sides halve the level's before it");
      picture.read_row(level, picture.height(level) / 2, 0, picture.width(level), rgb.data());
    }
  } catch (const std::runtime_error& e) {
    require_error(e.what(), path, "a region read's error is one line");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // In memory where the machine has it: a file made and removed for every input was a tenth of
  // an execution on a disk's file system.
  static const std::string folder = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path = folder + "/l2-fuzz-picture-" + std::to_string(::getpid()) + "." +
                           kExtensions[data[0] % std::size(kExtensions)];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    require(static_cast<bool>(out), "the input is written to its file");
  }
  read_whole(path);
  read_regions(path);
  ::unlink(path.c_str());
  return 0;
}
