// The hostile files of hostile_files.hpp through the pipeserver program (hostile_process.hpp
// says what each must do).
#include "hostile_process.hpp"

namespace l2::hostile_run {
namespace {

TEST_F(HostileProcess, ModelsAreRefusedInOneLine) {
  const std::string ply = hostile::ply_header("ascii") + hostile::kPlyAsciiBody;
  expect_refused({PIPESERVER_EXE, {"--mesh"}, {"--out", (dir_ / "out").string()}},
                 file("baseline.stl", "solid"),
                 {{"deep.gltf", hostile::gltf(hostile::node_chain(20000))},
                  {"twice.gltf", hostile::gltf(hostile::node_diamonds(40))},
                  {"json.gltf", hostile::gltf(hostile::node_chain(1),
                                              ", \"extras\": " + hostile::nested_arrays(1000000))},
                  {"big.glb", hostile::glb(0xFFFFFFF0u)},
                  {"deep.dae", hostile::collada_chain(17400)},
                  {"deep.x", hostile::x_frame_chain(20000)},
                  {"cut21.ply", ply.substr(0, 21)},
                  {"cut60.ply", ply.substr(0, 60)},
                  {"cut-end.ply", ply.substr(0, ply.find("end_header") + 4)},
                  {"list.ply", hostile::binary_ply_list(100000000)},
                  {"list-ascii.ply",
                   hostile::ply_header("ascii", "uint") + "0 0 0\n1 0 0\n0 1 0\n4000000000\n"},
                  {"counts.off", "OFF\n1000000000 1000000000 0\n0 0 0\n"},
                  {"nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"}});
}

TEST_F(HostileProcess, PicturesAreRefusedInOneLine) {
  const std::string small = hostile::small_png();
  expect_refused(
      {PIPESERVER_EXE, {"--scene", "picture", "--content"}, {"--out", (dir_ / "out").string()}},
      file("baseline.png", "not a picture\n"),
      {{"huge.png", hostile::png(100000, 100000, false, std::string(8, '\0'))},
       {"huge-interlaced.png", hostile::png(100000, 100000, true, std::string(8, '\0'))},
       {"cut.png", small.substr(0, small.size() / 2)},
       {"text.jpg", "not a picture\n"},
       {"bad.jpg", std::string("\xff\xd8\xff\xe0", 4) + std::string(60, 'x')},
       // Headers OpenImageIO believed (issue 54): aborts, a hang, gigabytes.
       {"wide.ppm", hostile::pnm_wide(2000000000)},
       {"wide.pfm", hostile::pfm_wide(2000000000)},
       {"tall.ppm", hostile::pnm_wide(1000000)},
       {"huge.jpg", hostile::jpeg_frame(65500, 65500)},
       {"huge.gif", hostile::gif_screen(16384, 16384)},
       {"levels.dds", hostile::dds_levels(0xFFFFFFFFu)}});
}

}  // namespace
}  // namespace l2::hostile_run
