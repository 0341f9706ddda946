// --picture-cache-mb through the program: a real pipeserver showing a tiled picture of 768 MiB
// decoded, zoomed out so that its first frame samples every tile under its own tiles (a
// quarter of the default wall's canvas, some 190 MiB of the picture), holds no more than the limit
// it was given beyond what the same pipeserver holds showing a small picture of the same format
// (the same reader, its libraries loaded); given a limit larger than the picture, it holds far
// more, so the limit is what bounds it. The pictures are written here with OpenImageIO a tile at
// a time, never whole.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "hostile_process.hpp"

namespace l2 {
namespace {

namespace OIIO = OIIO_NAMESPACE;
using hostile_run::Ended;
using hostile_run::HostileProcess;
namespace fs = std::filesystem;

constexpr int kSide = 16384, kTile = 64;
constexpr long kPictureMiB = 3L * kSide * kSide >> 20;  // 768
// What pipeserver 0 of the default wall samples of it: its tiles' quarter of the canvas.
constexpr long kShownMiB = kPictureMiB / 4;

void write_tiled_picture(const fs::path& path, int side) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(side, side, 3, OIIO::TypeDesc::UINT8);
  spec.tile_width = spec.tile_height = kTile;
  spec.attribute("compression", "zip");
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  std::vector<std::uint8_t> tile(3 * kTile * kTile);
  for (int ty = 0; ty < side; ty += kTile) {
    for (int tx = 0; tx < side; tx += kTile) {
      for (int y = 0; y < kTile; ++y) {
        for (int x = 0; x < kTile; ++x) {
          std::uint8_t* p = &tile[static_cast<std::size_t>(3 * (y * kTile + x))];
          p[0] = static_cast<std::uint8_t>(tx + x);
          p[1] = static_cast<std::uint8_t>(ty + y);
          p[2] = static_cast<std::uint8_t>((tx + x) ^ (ty + y));
        }
      }
      ASSERT_TRUE(out->write_tile(tx, ty, 0, OIIO::TypeDesc::UINT8, tile.data()))
          << out->geterror();
    }
  }
  ASSERT_TRUE(out->close());
}

class PictureCacheProcess : public HostileProcess {
 protected:
  // The pipeserver's peak in MiB rendering two frames of `scene_args` into a scan-out folder.
  long peak_mib(std::vector<std::string> scene_args) {
    std::vector<std::string> args{PIPESERVER_EXE};
    args.insert(args.end(), scene_args.begin(), scene_args.end());
    args.insert(args.end(), {"--count", "2", "--out", (dir_ / "scanout").string()});
    const Ended e = process_run::run(args, dir_ / "output.txt");
    EXPECT_EQ(e.code, 0) << e.output;
    return e.peak_kib / 1024;
  }
};

TEST_F(PictureCacheProcess, APipeserverHoldsNoMoreOfThePictureThanItsLimit) {
  const fs::path picture = dir_ / "tiled-16k.tif";
  write_tiled_picture(picture, kSide);
  const fs::path small = dir_ / "tiled-256.tif";
  write_tiled_picture(small, 256);
  const long base =
      peak_mib({"--scene", "picture", "--content", small.string(), "--picture-cache-mb", "16"});
  const long limited =
      peak_mib({"--scene", "picture", "--content", picture.string(), "--picture-cache-mb", "16"});
  const long unlimited =
      peak_mib({"--scene", "picture", "--content", picture.string(), "--picture-cache-mb", "4096"});
  std::printf(
      "peak memory: a 256x256 picture %ld MiB, this one at 16 MiB %ld MiB, at 4096 MiB %ld MiB\n",
      base, limited, unlimited);
  // The overhead allowed over the limit: the image cache's bookkeeping and a tile's reading
  // buffers per thread, the tiles' rows, the picture scene's own; a sixth of what it shows.
  constexpr long kOverheadMiB = kShownMiB / 6;
  EXPECT_LT(limited - base, 16 + kOverheadMiB)
      << "peak " << limited << " MiB, a 256x256 picture " << base << " MiB";
  // Without the limit the same frames hold most of what they show: the limit is what held it.
  EXPECT_GT(unlimited - base, kShownMiB / 2)
      << "peak " << unlimited << " MiB, a 256x256 picture " << base << " MiB";
}

}  // namespace
}  // namespace l2
