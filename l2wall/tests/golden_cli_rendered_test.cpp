// `l2wall golden` on a rendered entry (real pipeserver processes): images made by another Mesa
// are compared within the tolerance, and the output says so; update records this Mesa.
#include <fstream>

#include "golden_cli.hpp"
#include "golden_manifest.hpp"
#include "image/png_io.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2 {
namespace {

using namespace l2::test;

const std::string kBunny = "kd-2x2-bunny";

TEST_F(GoldenCli, AnotherMesaVersionIsComparedWithinTheToleranceAndUpdateRecordsThisOne) {
  GoldenManifest manifest = load_manifest(goldens() / "manifest.toml");
  for (GoldenEntry& e : manifest.entries) {
    if (e.name != kBunny) continue;
    e.mesa = "0.1.0";
    e.gl_version = "4.5 (Compatibility Profile) Mesa 0.1.0";
  }
  std::ofstream(goldens() / "manifest.toml") << format_manifest(manifest);
  RgbImage changed = read_png(golden(kBunny, 0));
  changed.set(200, 100, Rgb{255, 255, 254});
  write_png(golden(kBunny, 0), changed);

  const Result r = l2wall("check " + common() + " --entry " + kBunny + " --write-actual");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find(kBunny + ": golden images made with Mesa 0.1.0"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("compared within the tolerance"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(kBunny + ": emulator vs golden image: 1 of 1228800 pixels differ"),
            std::string::npos)
      << r.output;
  const RgbImage actual = read_png(out() / kBunny / "display-0-actual.png");

  const Result u = l2wall("update --goldens " + quote(goldens()) + " --out " + quote(out()) +
                          " --entry " + kBunny);
  EXPECT_EQ(u.code, 0) << u.output;
  EXPECT_NE(u.output.find("1 image written, manifest rewritten"), std::string::npos) << u.output;
  const GlInfo gl = gl_info();
  const GoldenManifest after = load_manifest(goldens() / "manifest.toml");
  const GoldenEntry* updated = after.find(kBunny);
  ASSERT_NE(updated, nullptr);
  EXPECT_EQ(updated->gl_version, gl.version);
  EXPECT_EQ(updated->gl_renderer, gl.renderer);
  EXPECT_EQ(updated->mesa, gl.mesa_version());
  EXPECT_TRUE(read_png(golden(kBunny, 0)) == actual);  // what this Mesa renders
}

}  // namespace
}  // namespace l2
