// Model and picture files made to hurt a reader that trusts them (hostile_files.hpp): each is
// refused in one line naming the file, and the field where there is one, before anything the
// file claims is allocated or walked. Issue 32 found a glTF node chain crashing the process, a
// PLY header cut short hanging it, and counts and lengths of a few bytes taking gigabytes.
// pipeserver_hostile_process_tests runs the same files through the program and measures it.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "image/png_io.hpp"
#include "pipeserver/hostile_files.hpp"
#include "pipeserver/model_file.hpp"
#include "pipeserver/scene.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

class Hostile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("l2_hostile_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes) const {
    hostile::write(dir_ / name, bytes);
    return dir_ / name;
  }
  // What loading the model says: the error, which must be one line, or "loaded".
  static std::string model_error(const fs::path& p) {
    try {
      load_mesh(p);
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return e.what();
    }
    return "loaded";
  }
  fs::path dir_;
};

// Assimp walks a glTF's nodes recursively: 20000 nested overflowed the stack (issue 32: 17400).
// As deep as the limit still loads.
TEST_F(Hostile, GltfNodesNestedPastTheLimitAreRefusedUpToItLoad) {
  const auto deep = file("deep.gltf", hostile::gltf(hostile::node_chain(20000)));
  EXPECT_EQ(model_error(deep), deep.string() +
                                   ": nodes nested 20000 deep (node 19999), more than the 1000 "
                                   "levels read here");
  const auto limit = file("limit.gltf", hostile::gltf(hostile::node_chain(1000)));
  EXPECT_EQ(load_mesh(limit).positions.size(), 3u);
}

// glTF 1.0 names its nodes: the message does too.
TEST_F(Hostile, Gltf1NodesNestedPastTheLimitAreNamed) {
  std::string nodes = R"({"asset": {"version": "1.0"}, "nodes": {)";
  for (int i = 0; i < 1200; ++i) {
    nodes += "\"n" + std::to_string(i) + R"(": {"children": ["n)" + std::to_string(i + 1) + "\"]},";
  }
  const auto deep = file("deep1.gltf", nodes + R"("n1200": {}}})");
  EXPECT_EQ(model_error(deep), deep.string() +
                                   ": nodes nested 1201 deep (node 'n1200'), more than the 1000 "
                                   "levels read here");
}

// A node listed twice (or by two parents) is copied once per path to it: forty levels of that
// asked for 2^40 copies.
TEST_F(Hostile, GltfNodeWithTwoParentsIsRefused) {
  const auto twice = file("twice.gltf", hostile::gltf(hostile::node_diamonds(40)));
  EXPECT_EQ(model_error(twice),
            twice.string() + ": node 1 is a child of node 0 twice (a glTF node has one parent)");
  const auto two =
      file("two.gltf", hostile::gltf(R"([{"children": [1, 2]}, {"children": [2]}, {"mesh": 0}])"));
  EXPECT_EQ(
      model_error(two),
      two.string() + ": node 2 is a child of node 0 and of node 1 (a glTF node has one parent)");
}

// Assimp walks a Collada file's nodes recursively too: 17,400 nested crashed the renderer
// (SIGSEGV, issue 54). The limit is passed at element level 1001, the node opened on line 1001
// (hostile::collada_chain); a chain that stays below loads. A DirectX text file's frames: the
// first opens on line 2, so level 1001 is on line 1002.
TEST_F(Hostile, ColladaNestedDeeperThanTheLimitIsRefused) {
  const auto deep = file("deep.dae", hostile::collada_chain(17400));
  EXPECT_EQ(model_error(deep),
            deep.string() + ": XML nested deeper than 1000 levels (at line 1001)");
  EXPECT_EQ(model_error(file("shallow.dae", hostile::collada_chain(900))), "loaded");
}

TEST_F(Hostile, DirectXTextNestedDeeperThanTheLimitIsRefused) {
  const auto deep = file("deep.x", hostile::x_frame_chain(20000));
  EXPECT_EQ(model_error(deep),
            deep.string() + ": braces nested deeper than 1000 levels (at line 1002)");
}

// Assimp's JSON parser is recursive too: a million nested arrays overflowed the stack. The
// file's own levels (the document and "extras") count.
TEST_F(Hostile, GltfJsonNestedPastTheLimitIsRefusedUpToItLoads) {
  const auto deep = file(
      "json.gltf",
      hostile::gltf(hostile::node_chain(1), ", \"extras\": " + hostile::nested_arrays(1000000)));
  EXPECT_EQ(model_error(deep), deep.string() + ": JSON nested deeper than 256 levels");
  const auto limit =
      file("limit.gltf",
           hostile::gltf(hostile::node_chain(1), ", \"extras\": " + hostile::nested_arrays(255)));
  EXPECT_EQ(load_mesh(limit).positions.size(), 3u);
  // A JSON document of another name is tried as glTF by Assimp all the same.
  const auto other = file("arrays.json", hostile::nested_arrays(1000000));
  EXPECT_EQ(model_error(other), other.string() + ": JSON nested deeper than 256 levels");
}

TEST_F(Hostile, GlbJsonChunkLongerThanTheFileIsRefused) {
  const auto glb = file("big.glb", hostile::glb(0xFFFFFFF0u));
  EXPECT_EQ(model_error(glb), glb.string() +
                                  ": its JSON chunk declares 4294967280 bytes, more than the "
                                  "file's 49");
}

// A header cut anywhere: Assimp waited for end_header for ever (issue 32: 21 bytes sufficed).
TEST_F(Hostile, PlyHeaderCutAnywhereIsOneLine) {
  const std::string whole = hostile::ply_header("ascii") + hostile::kPlyAsciiBody;
  const std::size_t end_header = whole.find("end_header");
  for (std::size_t cut = 1; cut < end_header + 10; ++cut) {
    const auto cut_file = file("cut.ply", whole.substr(0, cut));
    const std::string error = model_error(cut_file);
    if (cut < 3) {  // not "ply": Assimp's own line
      EXPECT_EQ(error.rfind(cut_file.string() + ": Invalid .ply file", 0), 0u) << cut << error;
    } else {
      EXPECT_EQ(error, cut_file.string() + ": the PLY header ends without end_header (cut short?)")
          << "cut at " << cut;
    }
  }
  EXPECT_EQ(load_mesh(file("whole.ply", whole)).positions.size(), 3u);
}

// A list's length is read from the body, and Assimp sized the list by it first: 1e8 took 800 MB,
// 4e9 ended in a bare "std::bad_alloc".
TEST_F(Hostile, PlyListLongerThanTheFileIsRefused) {
  for (const std::uint32_t length : {100000000u, 4000000000u}) {
    const auto binary = file("binary.ply", hostile::binary_ply_list(length));
    EXPECT_EQ(model_error(binary), binary.string() + ": face 0: list 'vertex_indices' declares " +
                                       std::to_string(length) +
                                       " values, more than the rest of the file can hold");
    const auto ascii =
        file("ascii.ply", hostile::ply_header("ascii", "uint") + "0 0 0\n1 0 0\n0 1 0\n" +
                              std::to_string(length) + " 0 1 2\n");
    EXPECT_EQ(model_error(ascii), ascii.string() + ": face 0: list 'vertex_indices' declares " +
                                      std::to_string(length) +
                                      " values, more than the rest of the file can hold");
  }
  // A negative length is one near 2^32 to Assimp.
  const auto negative = file(
      "negative.ply", hostile::ply_header("ascii", "char") + "0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n");
  EXPECT_EQ(model_error(negative), negative.string() +
                                       ": face 0: list 'vertex_indices' declares 4294967295 "
                                       "values, more than the rest of the file can hold");
  EXPECT_EQ(load_mesh(file("fits.ply", hostile::binary_ply_list(3))).indices.size(), 3u);
}

// A 309-byte OFF file declaring a billion vertices took 6 GB (issue 32).
TEST_F(Hostile, OffCountsBeyondTheFileAreRefused) {
  const auto vertices = file("vertices.off", "OFF\n1000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(model_error(vertices), vertices.string() +
                                       ": declares 1000000000 vertices and 1 faces, more than "
                                       "the rest of the file can hold (a line each)");
  const auto faces = file("faces.off", "OFF\n# a comment\n3 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_EQ(model_error(faces), faces.string() +
                                    ": declares 3 vertices and 1000000000 faces, more than the "
                                    "rest of the file can hold (a line each)");
  EXPECT_EQ(
      load_mesh(file("fits.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).indices.size(), 3u);
}

// OBJ declares no counts; a coordinate written as nan or inf is read as one, and refused.
TEST_F(Hostile, ObjNanAndInfinityAreRefused) {
  for (const std::string word : {"nan", "inf", "-inf", "1e999"}) {
    const auto obj = file("v.obj", "v 0 0 0\nv 1 " + word + " 0\nv 0 1 0\nf 1 2 3\n");
    const std::string shown = word == "1e999" ? "inf" : word;
    EXPECT_EQ(model_error(obj),
              obj.string() + ": vertex 1: y = " + shown + " is not a finite float");
  }
}

// What the picture scene says of a picture, or "opened".
std::string picture_error(const fs::path& p) {
  SceneOptions options;
  options.content = p;
  try {
    make_scene("picture", options);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "opened";
}

// The picture scene refuses `f` in one line, "F: cannot read: " and `said`, printing nothing.
void expect_refused(const fs::path& f, const std::string& said) {
  ::testing::internal::CaptureStderr();
  const std::string error = picture_error(f);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << f;
  EXPECT_EQ(error, f.string() + ": cannot read: " + said);
}

// A PNG claiming 100000x100000 pixels in 70 bytes was read row by row until libpng (printing its
// own line first) ran out of data; interlaced, the image cache aborted the process.
TEST_F(Hostile, PngClaimingMorePixelsThanItsDataHoldsIsOneLineAndPrintsNothing) {
  for (const bool interlaced : {false, true}) {
    const auto huge =
        file("huge.png", hostile::png(100000, 100000, interlaced, std::string(8, '\0')));
    ::testing::internal::CaptureStderr();
    const std::string error = picture_error(huge);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(error, huge.string() +
                         ": cannot read: a PNG of 100000x100000 pixels whose image data, 19 bytes, "
                         "is too little to hold them (cut short or damaged)");
  }
  EXPECT_EQ(picture_error(file("small.png", hostile::small_png())), "opened");
}

// An interlaced PNG is read whole: past what a picture read whole may take it is refused before
// the cache sees it. Its image data is as much as such a picture compresses to at best.
TEST_F(Hostile, AnInterlacedPngTooLargeToReadWholeIsRefused) {
  const std::uint32_t side = 14000;
  const auto big = file("big.png", hostile::png(side, side, true, std::string(600000, '\0')));
  EXPECT_EQ(picture_error(big), big.string() +
                                    ": cannot read: an interlaced PNG of 14000x14000 pixels is "
                                    "read whole, 560 MiB, more than a picture read whole may take "
                                    "(512 MiB of cache); save it without interlacing");
}

TEST_F(Hostile, PngCutShortAnywhereIsOneLine) {
  const std::string whole = hostile::small_png();
  const std::size_t iend = whole.size() - 12;
  for (std::size_t cut = 9; cut < iend; ++cut) {
    const auto cut_file = file("cut.png", whole.substr(0, cut));
    ::testing::internal::CaptureStderr();
    const std::string error = picture_error(cut_file);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << cut;
    EXPECT_EQ(error, cut_file.string() + ": cannot read: the PNG file ends early (truncated)")
        << "cut at " << cut;
  }
}

// Headers of other formats that OpenImageIO believed (issue 54): a PPM or PFM declaring a width
// of 2e9 aborted the process in the image cache, a JPEG saying 65500x65500 was decoded for ever,
// a 35-byte GIF of 16384x16384 took 1.2 GB, a DDS declaring 2^32-1 mip levels hung its opening.
// Each is refused in one line saying what it declares, and nothing is printed besides; the
// same files, 8x8 as they are, open.
TEST_F(Hostile, OtherFormatsDeclaringMoreThanTheyHoldAreOneLine) {
  const auto expect = [&](const std::string& name, const std::string& bytes,
                          const std::string& said) { expect_refused(file(name, bytes), said); };
  expect("wide.ppm", hostile::pnm_wide(2000000000),
         "declares 2000000000x1 pixels, more than any wall shows (up to 1048576 a side, 64 "
         "gigapixels)");
  expect("wide.pfm", hostile::pfm_wide(2000000000),
         "declares 2000000000x1 pixels, more than any wall shows (up to 1048576 a side, 64 "
         "gigapixels)");
  // 1000000 x 1 x 3 bytes = 3 MB from 300 bytes of samples (317 with its 17-byte header).
  expect("long.ppm", hostile::pnm_wide(1000000),
         "declares 1000000x1 pixels of 3 channels (3 MiB decoded), more than a pnm file of 317 "
         "bytes can hold");
  expect("huge.jpg", hostile::jpeg_frame(65500, 65500),
         "declares 65500x65500 pixels of 3 channels (12275 MiB decoded), more than a jpeg file "
         "of 202 bytes can hold");
  expect("huge.gif", hostile::gif_screen(16384, 16384),
         "declares 16384x16384 pixels of 4 channels (1024 MiB decoded), more than a gif file of "
         "35 bytes can hold");
  expect("levels.dds", hostile::dds_levels(0xFFFFFFFFu),
         "a DDS of 8x8 declaring 4294967295 mipmap levels, more than its sides (4) or its 512 "
         "bytes allow");
  EXPECT_EQ(picture_error(file("small.jpg", hostile::jpeg_frame(8, 8))), "opened");
  EXPECT_EQ(picture_error(file("small.gif", hostile::gif_screen(1, 1))), "opened");
  EXPECT_EQ(picture_error(file("small.dds", hostile::dds_levels(1))), "opened");
}

// The other formats the picture scene reads (issue 54): TIFF, striped and tiled, BMP, Radiance
// HDR, FITS and an ICO holding a PNG, each declaring more than its bytes hold, than a wall
// shows or than a reader may hold; a TIFF of more directories than its reader opens in time
// (20,000 held the picture scene for minutes, each opened by walking the chain from the first).
// Refused in one line saying what the file declares, nothing printed besides; the same files of
// 8x8 pixels open.
TEST_F(Hostile, EveryFormatDeclaringMoreThanItHoldsIsOneLine) {
  const auto expect = [&](const std::string& name, const std::string& bytes,
                          const std::string& said) { expect_refused(file(name, bytes), said); };
  const std::string wider_than_a_wall =
      " pixels, more than any wall shows (up to 1048576 a side, 64 gigapixels)";
  expect("wide.tif", hostile::tiff({.width = 2000000000, .height = 1}),
         "declares 2000000000x1" + wider_than_a_wall);
  expect("tall.tif", hostile::tiff({.width = 1, .height = 4294967295u}),
         "declares 1x4294967295" + wider_than_a_wall);
  // 1024 x 1024 x 3 bytes = 3 MiB, from a file of 8 + (2 + 10 x 12 + 4) + 300 = 434 bytes (ten
  // tags).
  expect("tiled.tif", hostile::tiff({.width = 1024, .height = 1024, .tile = 65536}),
         "declares 1024x1024 pixels of 3 channels (3 MiB decoded), more than a tiff file of 434 "
         "bytes can hold");
  // 256 x 256 x 3 bytes in 134 + 4000 bytes (within 64 to 1), in tiles of 65536^2 x 3 bytes.
  expect("tiles.tif",
         hostile::tiff({.width = 256, .height = 256, .tile = 65536, .data = std::string(4000, 0)}),
         "tiles of 65536x65536 pixels (12288 MiB each), more than the 64 MiB a reader holds");
  expect("samples.tif", hostile::tiff({.samples = 60000}),
         "declares 8x8x1 pixels of 60000 channels of 1 bytes, not a picture");
  expect("pages.tif", hostile::tiff({.width = 1, .height = 1, .directories = 300, .data = "abc"}),
         "a TIFF of more than 256 directories (pages or levels), more than its reader opens in "
         "time; the first is shown: save it alone");
  expect("wide.bmp", hostile::bmp(2000000000, 1), "declares 2000000000x1" + wider_than_a_wall);
  expect("tall.bmp", hostile::bmp(1, -2000000000), "declares 1x2000000000" + wider_than_a_wall);
  // 30000^2 x 3 bytes = 2575 MiB, rounded up, from 354 bytes.
  expect("big.bmp", hostile::bmp(30000, 30000),
         "declares 30000x30000 pixels of 3 channels (2575 MiB decoded), more than a bmp file of "
         "354 bytes can hold");
  expect("wide.hdr", hostile::hdr(2000000000, 1), "declares 2000000000x1" + wider_than_a_wall);
  // 100000^2 x 3 floats = 111,759 MiB... as 4-byte floats: 120,000,000,000 bytes.
  expect("big.hdr", hostile::hdr(100000, 100000),
         "declares 100000x100000 pixels of 3 channels (114441 MiB decoded), more than a hdr file "
         "of 355 bytes can hold");
  expect("wide.fits", hostile::fits(2000000000, 1), "declares 2000000000x1" + wider_than_a_wall);
  expect("big.fits", hostile::fits(100000, 100000),
         "declares 100000x100000 pixels of 1 channels (9537 MiB decoded), more than a fits file "
         "of 5760 bytes can hold");
  const std::string huge_png = hostile::png(100000, 100000, false, std::string(8, '\0'));
  expect("huge.ico", hostile::ico(huge_png),
         "declares 100000x100000 pixels of 3 channels (28611 MiB decoded), more than a ico file "
         "of " +
             std::to_string(22 + huge_png.size()) + " bytes can hold");
  // An icon's PNG is decoded whole: 16384^2 x 3 bytes is 768 MiB, which 100 kB of deflate
  // could hold.
  expect("whole.ico", hostile::ico(hostile::png(16384, 16384, false, std::string(100000, '\0'))),
         "a ico of 16384x16384 pixels is decoded whole, 768 MiB, more than the 512 MiB a picture "
         "read whole may take; save it as a tiled TIFF");
  // OpenImageIO's ICO reader crashed the process (SIGFPE) on a PNG icon cut short, and let
  // libpng print its own line on a damaged one: libpng reads them first.
  expect("cut.ico", hostile::ico(hostile::small_png().substr(0, 40)),
         "an ICO's image 0: the PNG file ends early (truncated)");
  expect("damaged.ico", hostile::ico(hostile::small_png(true)),
         "an ICO's image 0: a damaged PNG (IDAT: incorrect data check)");
  // A PNG to the reader by its bytes 1 to 3 alone: one whose signature is damaged after them
  // and its first chunk's length beyond 2^31 crashed it too.
  expect("signature.ico", hostile::ico(hostile::damaged_signature_png()),
         "an ICO's image 0: a damaged PNG (PNG file corrupted by ASCII conversion)");
  // 1.6 GB asked of the allocator by a 27-byte file (fuzz_picture_file found it).
  expect("attribute.exr", hostile::exr_attribute(1677721600),
         "an OpenEXR attribute 'junk' of type 'opaque' declaring 1677721600 bytes, more than the "
         "3 the file has left");
  expect("no-green.dds", hostile::dds_no_green(),
         "a DDS whose green bit mask is zero, no channel its reader can unpack");
  EXPECT_EQ(picture_error(file("small.tif", hostile::tiff({}))), "opened");
  EXPECT_EQ(picture_error(
                file("small-tiled.tif", hostile::tiff({.tile = 16, .data = std::string(768, 0)}))),
            "opened");
  EXPECT_EQ(picture_error(file("pages.tif", hostile::tiff({.directories = 256}))), "opened");
  EXPECT_EQ(picture_error(file("small.bmp", hostile::bmp(8, 8))), "opened");
  EXPECT_EQ(picture_error(file("small.hdr", hostile::hdr(8, 8))), "opened");
  EXPECT_EQ(picture_error(file("small.fits", hostile::fits(8, 8))), "opened");
  EXPECT_EQ(picture_error(file("small.ico", hostile::ico(hostile::small_png()))), "opened");
}

// A whole picture's read (read_png: strip_headers dump, lightning2_emu route, a model's
// texture) checks the same: a 434-byte TIFF of 1024x1024 pixels in a tile of 65536x65536 took
// 13 GB and a minute before, within every caller's bound on the sides.
TEST_F(Hostile, AWholeReadChecksWhatTheFileDeclares) {
  const auto tiled =
      file("tiled.tif", hostile::tiff({.width = 1024, .height = 1024, .tile = 65536}));
  const auto error = [](const fs::path& f) {
    try {
      read_png(f);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(error(tiled), tiled.string() +
                              ": cannot read: declares 1024x1024 pixels of 3 channels (3 MiB "
                              "decoded), more than a tiff file of 434 bytes can hold");
  const auto pages = file(
      "pages.tif", hostile::tiff({.width = 1, .height = 1, .directories = 300, .data = "abc"}));
  EXPECT_EQ(
      error(pages).rfind(pages.string() + ": cannot read: a TIFF of more than 256 directories", 0),
      0u);
  const RgbImage small =
      read_png(file("small.tif", hostile::tiff({.data = std::string(192, '\x40')})));
  EXPECT_EQ(small.width(), 8);
  EXPECT_EQ(small.at(7, 7), (Rgb{0x40, 0x40, 0x40}));
}

// A PNG whose image data fails zlib's check: the image cache's reader printed libpng's own line
// ("libpng error: IDAT: incorrect data check") before ours, a frame into the run. Its rows are
// decoded before the cache sees it: one line, with libpng's reason, nothing printed.
TEST_F(Hostile, APngWithDamagedDataIsOneLineWithTheLibrarysReason) {
  expect_refused(file("damaged.png", hostile::small_png(true)),
                 "a damaged PNG (IDAT: incorrect data check)");
  const auto whole = file("whole.png", hostile::small_png());
  EXPECT_EQ(picture_error(whole), "opened");
}

// Named as a picture, holding something else: OpenImageIO's reasons were several lines.
TEST_F(Hostile, APictureThatIsNotOneIsOneLine) {
  const auto text_png = file("text.png", "not a picture\n");
  EXPECT_EQ(picture_error(text_png), text_png.string() + ": cannot read: Not a PNG file");
  const auto text_jpg = file("text.jpg", "not a picture\n");
  EXPECT_EQ(picture_error(text_jpg).rfind(text_jpg.string() + ": cannot read: ", 0), 0u);
  const auto bad_jpeg = file("bad.jpg", std::string("\xff\xd8\xff\xe0", 4) + std::string(60, 'x'));
  const std::string error = picture_error(bad_jpeg);
  EXPECT_EQ(error.rfind(bad_jpeg.string() + ": cannot read: a JPEG file: ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  const auto png_named_jpg = file("png.jpg", hostile::small_png());  // read by its content
  EXPECT_EQ(picture_error(png_named_jpg), "opened");
}

}  // namespace
}  // namespace l2
