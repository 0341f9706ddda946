// Pictures of every format OpenImageIO reads for the wall, declaring more than their bytes hold
// (issue 54), through the programs that read pictures: the picture scene of a pipeserver (a
// part at a time, through the image cache) and the whole reads of strip_headers dump and
// lightning2_emu route. Before, a 434-byte TIFF of 1024x1024 pixels in one tile of 65536x65536
// took 13 GB and a minute in dump and route, and a 2.3 MB TIFF of 20,000 one-pixel directories
// held the picture scene for minutes, and an ICO holding a PNG cut short crashed every one of
// them (SIGFPE in OpenImageIO's ICO reader), as a well-formed 12x12 ICO of 4 bits a pixel did
// (its mask written past the reader's buffer); an RLA of 4x4 pixels with an auxiliary channel of 0
// bits, and 177 bytes of JPEG 2000 named .tga (a format not read here), hung them.
// hostile_process.hpp says what each run must do.
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "hostile_process.hpp"

namespace l2::hostile_run {
namespace {

// A fuzz_picture_file finding kept as found among the seeds (fuzz/make-seeds.py writes them),
// without the byte that picks its extension.
std::string seed(const std::string& name) {
  std::ifstream in(std::string(L2_SOURCE_DIR) + "/fuzz/corpus/picture_file/" + name,
                   std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 2) throw std::runtime_error("no seed " + name);
  return bytes.substr(1);
}

// A 64x64 picture in tiles of 16, then `level`.
std::string pyramid(const hostile::Tiff& level) {
  hostile::Tiff first{.width = 64, .height = 64, .tile = 16, .data = std::string(64 * 64 * 3, 0)};
  first.more = {level};
  return hostile::tiff(first);
}

// One of each: what the header declares against the file's bytes, a wall, a tile a reader
// holds, a picture decoded whole, the channels any picture has, the directories a reader opens.
std::vector<std::pair<std::string, std::string>> every_format() {
  const std::string huge_png = hostile::png(100000, 100000, false, std::string(8, '\0'));
  return {
      {"wide.tif", hostile::tiff({.width = 2000000000, .height = 1})},
      {"tall.tif", hostile::tiff({.width = 1, .height = 4294967295u})},
      {"tiled.tif", hostile::tiff({.width = 1024, .height = 1024, .tile = 65536})},
      {"tiles.tif",
       hostile::tiff({.width = 256, .height = 256, .tile = 65536, .data = std::string(4000, 0)})},
      {"samples.tif", hostile::tiff({.samples = 60000})},
      {"pages.tif", hostile::tiff({.width = 1, .height = 1, .directories = 20000, .data = "abc"})},
      // Pyramids: a level after a fine first directory declaring tiles of 65536, tiles of one
      // side 0, or more pixels than the file holds.
      {"level-tiles.tif", pyramid({.width = 32, .height = 32, .tile = 65536})},
      {"level-tile-zero.tif", pyramid({.width = 32, .height = 32, .tile = 16, .tile_length = 0})},
      {"level-past.tif", pyramid({.width = 100000, .height = 100000, .tile = 16})},
      {"wide.bmp", hostile::bmp(2000000000, 1)},
      {"tall.bmp", hostile::bmp(1, -2000000000)},
      {"big.bmp", hostile::bmp(30000, 30000)},
      {"wide.hdr", hostile::hdr(2000000000, 1)},
      {"big.hdr", hostile::hdr(100000, 100000)},
      {"wide.fits", hostile::fits(2000000000, 1)},
      {"big.fits", hostile::fits(100000, 100000)},
      {"e20.ppm", "P6\n100000000000000000000 1\n255\n" + std::string(300, '\0')},
      {"huge.ico", hostile::ico(huge_png)},
      {"cut.ico", hostile::ico(hostile::small_png().substr(0, 40))},
      {"no-green.dds", hostile::dds_no_green()},
      {"chunk.exr", hostile::exr_window(1000000, 64, 26, 4)},
      {"zero.sgi", hostile::sgi(0, 0)},
      {"storage.sgi", hostile::sgi(64, 1)},
      {"tables.sgi", hostile::sgi_empty_tables()},
      {"alpha.dds", hostile::dds_alpha_alone()},
      {"axes.fits", hostile::fits_missing_axis()},
      {"strips.tif", hostile::tiff_tall_strips()},
      {"header.ico", hostile::ico_bitmap(2304, 32)},
      {"bits.ico", hostile::ico_bitmap(40, 7)},
      {"mask.ico", hostile::ico_bitmap(40, 4, 12, 16)},
      {"palette.ico", hostile::ico_bitmap(40, 8, 8, 2)},
      {"signature.ico", hostile::ico(hostile::damaged_signature_png())},
      {"bits.rla", hostile::rla(0, 8, 1, 0)},
      {"words.rla", hostile::rla(1, 20, 0, 0)},
      {"type.rla", hostile::rla(3, 8, 0, 0)},
      {"next.rla", hostile::rla(0, 8, 0, 0).replace(736, 4, "\xFF\xFF\xFF\xFF")},
      {"garbage.rla", seed("next-offset-garbage.rla")},
      {"bits.dds", seed("bits-a-pixel.dds")},
      {"cut-strips.tif", seed("strips-no-next-offset.tif")},
      {"naxis.fits", hostile::fits(9, 4).replace(170, 20, std::string(20, '7'))},
      {"whole.ico", hostile::ico(hostile::png(16384, 16384, false, std::string(100000, '\0')))},
      // A format no check bounds, under its own name and another's.
      {"wide.j2k", hostile::jpeg2000(60000)},
      {"jpeg2000.tga", hostile::jpeg2000(1000000)},
      {"jpeg2000.png", hostile::jpeg2000(60000)},
  };
}

TEST_F(HostileProcess, PicturesOfEveryFormatAreRefusedInOneLine) {
  expect_refused(
      {PIPESERVER_EXE, {"--scene", "picture", "--content"}, {"--out", (dir_ / "out").string()}},
      file("baseline.tif", "not a picture\n"), every_format());
}

// The whole reads: each caller bounds the sides (4096 for dump, the board's for route); within
// them, what the file declares is checked as the picture scene checks it.
TEST_F(HostileProcess, WholeReadsOfEveryFormatAreRefusedInOneLine) {
  std::vector<std::pair<std::string, std::string>> files;
  for (auto& [name, bytes] : every_format()) {
    if (name == "tiled.tif" || name == "tiles.tif" || name == "samples.tif" ||
        name == "pages.tif" || name == "cut.ico" || name == "no-green.dds" ||
        name == "tables.sgi" || name == "alpha.dds" || name == "axes.fits" ||
        name.find(".rla") != std::string::npos || name == "mask.ico" || name == "palette.ico" ||
        name == "naxis.fits" || name == "bits.dds" || name.find("j2k") != std::string::npos ||
        name.find("jpeg2000") == 0)
      files.emplace_back(name, bytes);
  }
  files.insert(files.end(),
               {{"big.bmp", hostile::bmp(1024, 1024)},
                {"big.hdr", hostile::hdr(1024, 1024)},
                {"big.fits", hostile::fits(1024, 1024)},
                {"big.ico", hostile::ico(hostile::png(1024, 1024, false, std::string(8, '\0')))}});
  const fs::path baseline = file("baseline.tif", "not a picture\n");
  expect_refused({STRIP_HEADERS_EXE, {"dump"}, {}}, baseline, files);
  expect_refused(
      {L2_EMU_EXE, {"route", "--displays", "1280x1024", "--out", (dir_ / "out").string()}, {}},
      baseline, files);
}

// A PNG whose image data fails zlib's check, in the picture scene: libpng's own line
// ("libpng error: IDAT: incorrect data check") came before ours, a frame into the run. Now the
// whole output is one line naming the file, with libpng's reason, and the run never starts.
TEST_F(HostileProcess, APngWithDamagedDataIsOneLineWithTheLibrarysReason) {
  const fs::path damaged = file("damaged.png", hostile::small_png(true));
  const Ended e = run_on(
      {PIPESERVER_EXE, {"--scene", "picture", "--content"}, {"--out", (dir_ / "out").string()}},
      damaged);
  EXPECT_EQ(e.code, 1);
  EXPECT_EQ(e.output, "pipeserver: " + damaged.string() +
                          ": cannot read: a damaged PNG (IDAT: incorrect data check)\n");
}

}  // namespace
}  // namespace l2::hostile_run
