// The two renderers behind GlContext (gl_context.hpp): OSMesa, and EGL, here Mesa's llvmpipe on
// Mesa's software device. They give the same pixels, byte for byte, on every example wall and
// with every built-in scene (every pipeserver's scanned-out frame and every display's reference),
// and on pictures, sessions, a textured model and a program's own drawing; each context draws
// through its own renderer's functions, also when contexts of both take turns on one thread;
// `--renderer auto` picks OSMesa where there is no GPU and says why; an EGL that cannot render is
// one line from the pipeserver, and `auto` then falls back to OSMesa.
#include <EGL/egl.h>
#include <dlfcn.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "pipeserver/gl_context.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_scenes.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// A GPU's render node: where one is, `auto` may rightly pick EGL, and EGL need not be llvmpipe.
bool has_gpu_node() {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/dev/dri", ec))
    if (e.path().filename().string().rfind("renderD", 0) == 0) return true;
  return false;
}

// Every pipeserver's frame and every display's reference render of `frame`, with `renderer`.
struct Rendered {
  std::vector<RgbImage> frames, references;
};
Rendered render_all(RendererChoice renderer, const TileLayout& layout, const std::string& name,
                    const SceneOptions& options, int frame) {
  use_renderer(renderer);
  auto scene = make_scene(name, options);
  Rendered out;
  for (int i = 0; i < static_cast<int>(layout.pipeservers.size()); ++i) {
    Pipeserver ps(layout, i);
    out.frames.push_back(ps.render_frame(frame, *scene));
  }
  for (const Display& d : layout.wall.displays)
    out.references.push_back(render_reference(layout, d.id, *scene, frame));
  return out;
}

void expect_same(const std::vector<RgbImage>& osmesa, const std::vector<RgbImage>& egl,
                 const char* what) {
  ASSERT_EQ(osmesa.size(), egl.size());
  for (std::size_t i = 0; i < osmesa.size(); ++i) {
    ASSERT_EQ(osmesa[i].width(), egl[i].width()) << what << " " << i;
    ASSERT_EQ(osmesa[i].height(), egl[i].height()) << what << " " << i;
    const test::ImageDiff d = test::compare(osmesa[i], egl[i]);
    EXPECT_EQ(d.pixels_differing, 0)
        << what << " " << i << ": " << d.pixels_differing << " pixels differ between OSMesa and "
        << "EGL, by up to " << d.max_channel_diff;
  }
}

void expect_renderers_alike(const TileLayout& layout, const std::string& name,
                            const SceneOptions& options, int frame) {
  const Rendered osmesa = render_all(RendererChoice::OsMesa, layout, name, options, frame);
  const Rendered egl = render_all(RendererChoice::Egl, layout, name, options, frame);
  expect_same(osmesa.frames, egl.frames, "pipeserver");
  expect_same(osmesa.references, egl.references, "reference of display");
  // Something was drawn: a black wall would be alike too.
  long lit = 0;
  for (const RgbImage& r : osmesa.references)
    for (int y = 0; y < r.height(); ++y)
      for (int x = 0; x < r.width(); ++x) lit += !(r.at(x, y) == Rgb{});
  EXPECT_GT(lit, 0);
  use_renderer(RendererChoice::OsMesa);
}

// Each example wall with one scene and each scene on some wall: the renderers differ in how a
// context is made and read back (its size, its framebuffer's orientation), which every wall's
// framebuffer sizes and every scene's drawing calls exercise, not in rasterising, which both
// leave to the same Mesa. ExampleWall (example_walls_test.cpp) sweeps every pair for routing.
class RenderersOnExampleWall : public ::testing::TestWithParam<test::WallScene> {};

TEST_P(RenderersOnExampleWall, GiveTheSamePixels) {
  const auto& [path, name] = GetParam();
  SCOPED_TRACE(path.filename().string() + " " + name);
  expect_renderers_alike(plan_layout(load_wall(path)), name, test::small_options(), 3);
}

INSTANTIATE_TEST_SUITE_P(Walls, RenderersOnExampleWall,
                         ::testing::ValuesIn(test::diagonal_wall_scenes()), test::wall_scene_name);

// A packed stereo display's halves are windows of half its size, each read back alone.
TEST(Renderers, GiveTheSamePixelsOnPackedStereoWalls) {
  for (const char* wall : {"stereo-side-by-side-2x1.toml", "stereo-top-bottom-2x1.toml"}) {
    SCOPED_TRACE(wall);
    expect_renderers_alike(
        plan_layout(load_wall(std::filesystem::path(L2_SOURCE_DIR) / "examples/walls" / wall)),
        "mesh", test::small_options(), 3);
  }
}

// Pictures (glDrawPixels), a session of windows over a background, a model's texture.
TEST(Renderers, GiveTheSamePixelsOnPicturesSessionsAndTextures) {
  const TileLayout layout = plan_layout(default_wall());
  SceneOptions session;
  session.session = fs::path(L2_SOURCE_DIR) / "examples" / "sessions" / "windows.toml";
  expect_renderers_alike(layout, "session", session, 2);
  SceneOptions picture;
  picture.content = fs::path(L2_SOURCE_DIR) / "docs" / "images" / "bunny-default-wall.png";
  expect_renderers_alike(layout, "picture", picture, 5);
  // assimp-testmodels (scripts/install-deps.sh): the Khronos sample, its texture embedded.
  SceneOptions textured;
  textured.mesh_file = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  expect_renderers_alike(layout, "mesh", textured, 4);
}

// A program's own drawing (renderer.hpp): immediate mode through l2::gl().
TEST(Renderers, GiveTheSamePixelsForAProgramsOwnDrawing) {
  const TileLayout layout = plan_layout(default_wall());
  const auto draw = [](const TileView& view) {
    const GlApi& gl = l2::gl();
    gl.Rotatef(7.0f * static_cast<float>(view.frame), 0.3f, 1, 0);
    gl.Begin(GL_TRIANGLES);
    for (int i = 0; i < 12; ++i) {
      const float a = 0.52f * static_cast<float>(i);
      gl.Color3f(0.2f + 0.06f * static_cast<float>(i), 0.9f - 0.05f * static_cast<float>(i), 0.5f);
      gl.Vertex3f(0.0f, 0.0f, 0.3f);
      gl.Vertex3f(0.9f * std::cos(a), 0.9f * std::sin(a), -0.2f);
      gl.Vertex3f(0.9f * std::cos(a + 0.45f), 0.9f * std::sin(a + 0.45f), 0.1f);
    }
    gl.End();
  };
  Rendered both[2];
  for (int r = 0; r < 2; ++r) {
    use_renderer(r == 0 ? RendererChoice::OsMesa : RendererChoice::Egl);
    auto scene = make_own_scene(draw);
    for (int i = 0; i < static_cast<int>(layout.pipeservers.size()); ++i) {
      Pipeserver ps(layout, i);
      both[r].frames.push_back(ps.render_frame(6, *scene));
    }
  }
  expect_same(both[0].frames, both[1].frames, "pipeserver");
  use_renderer(RendererChoice::OsMesa);
}

// The library a GL function of the current context's table lives in.
std::string library_of(void* function) {
  Dl_info info{};
  if (dladdr(function, &info) == 0 || info.dli_fname == nullptr) return "(none)";
  return fs::path(info.dli_fname).filename().string();
}

std::vector<std::uint8_t> pixel(const GlContext& c, int x, int y) {
  const std::uint8_t* p = c.rgba() + (static_cast<std::size_t>(y) * c.width() + x) * 4;
  return {p[0], p[1], p[2]};
}

// OSMesa's functions are libOSMesa's own (its dispatch, libglapi); EGL's are glvnd's dispatch
// (libGLdispatch), which reaches whichever vendor's context EGL made current: the GPU's driver on
// a GPU node. Contexts of both renderers take turns on one thread and draw only into their own.
TEST(Renderers, EachContextDrawsThroughItsOwnRenderer) {
  GlContext osmesa(16, 8, Renderer::OsMesa);
  const std::string osmesa_library = library_of(reinterpret_cast<void*>(gl().Clear));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  GlContext egl(16, 8, Renderer::Egl);
  const std::string egl_library = library_of(reinterpret_cast<void*>(gl().Clear));
  EXPECT_NE(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(egl_library.rfind("libGLdispatch.so", 0), 0u) << egl_library;
  EXPECT_EQ(osmesa_library.find("libGLdispatch"), std::string::npos) << osmesa_library;
  EXPECT_NE(osmesa_library, "(none)");

  // EGL's context draws into a pbuffer of its own: its framebuffer is the default one, as
  // OSMesa's is (a framebuffer object would rasterise upside down: egl_surface.cpp).
  GLint framebuffer = -1;
  gl().GetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
  EXPECT_EQ(framebuffer, 0);

  // Green everywhere in EGL's, red in OSMesa's, then blue over EGL's left half.
  gl().ClearColor(0, 1, 0, 1);
  gl().Clear(GL_COLOR_BUFFER_BIT);
  osmesa.make_current();
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  gl().ClearColor(1, 0, 0, 1);
  gl().Clear(GL_COLOR_BUFFER_BIT);
  egl.make_current();
  gl().Enable(GL_SCISSOR_TEST);
  gl().Scissor(0, 0, 8, 8);
  gl().ClearColor(0, 0, 1, 1);
  gl().Clear(GL_COLOR_BUFFER_BIT);
  gl().Disable(GL_SCISSOR_TEST);
  egl.finish();
  osmesa.finish();
  const std::vector<std::uint8_t> red{255, 0, 0}, green{0, 255, 0}, blue{0, 0, 255};
  EXPECT_EQ(pixel(osmesa, 2, 3), red);
  EXPECT_EQ(pixel(osmesa, 12, 3), red);
  EXPECT_EQ(pixel(egl, 2, 3), blue);
  EXPECT_EQ(pixel(egl, 12, 3), green);
  use_renderer(RendererChoice::OsMesa);
}

TEST(Renderers, NoContextCurrentIsALogicErrorNotACrash) {
  use_renderer(RendererChoice::OsMesa);  // leaves none current
  EXPECT_THROW(gl(), std::logic_error);
}

TEST(RendererDecision, AutoPicksOsMesaWithoutAGpuAndSaysWhy) {
  if (has_gpu_node()) GTEST_SKIP() << "this machine has a GPU's render node";
  const RendererDecision d = use_renderer(RendererChoice::Auto);
  EXPECT_EQ(d.renderer, Renderer::OsMesa);
  EXPECT_EQ(process_renderer(), Renderer::OsMesa);
  EXPECT_EQ(d.why, "auto: no GPU: EGL finds only Mesa's software device (llvmpipe)");
  EXPECT_EQ(d.line().rfind("osmesa (llvmpipe", 0), 0u) << d.line();
  EXPECT_NE(d.line().find("; auto: no GPU: "), std::string::npos) << d.line();
}

TEST(RendererDecision, EglForcedRunsOnLlvmpipeThroughEglHere) {
  if (has_gpu_node()) GTEST_SKIP() << "this machine has a GPU's render node";
  const RendererDecision d = use_renderer(RendererChoice::Egl);
  EXPECT_EQ(d.renderer, Renderer::Egl);
  EXPECT_EQ(process_renderer(), Renderer::Egl);
  EXPECT_EQ(d.device, "Mesa's software device");
  EXPECT_NE(d.gl_renderer.find("llvmpipe"), std::string::npos) << d.gl_renderer;
  EXPECT_EQ(d.why, "--renderer egl");
  // OSMesa and EGL on llvmpipe name themselves alike (golden images record these strings).
  const GlInfo osmesa = gl_info(Renderer::OsMesa);
  EXPECT_EQ(d.gl_renderer, osmesa.renderer);
  EXPECT_EQ(d.gl_version, osmesa.version);
  GlContext context(4, 4);
  EXPECT_EQ(context.renderer(), Renderer::Egl);
  use_renderer(RendererChoice::OsMesa);
}

// `pipeserver ARGS` with `environment` ("NAME=value ..."): its exit code and its stdout and
// stderr together.
struct Ended {
  int code = -1;
  std::string output;
};
Ended run_pipeserver(const std::string& environment, const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2_renderers_{}", getpid());
  fs::create_directories(dir);
  const fs::path output = dir / "output.txt";
  const std::string command =
      fmt::format("env {} '{}' {} --out '{}' > '{}' 2>&1", environment, PIPESERVER_EXE, args,
                  (dir / "out").string(), output.string());
  const int status = std::system(command.c_str());
  Ended e;
  e.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(output);
  e.output.assign(std::istreambuf_iterator<char>(in), {});
  fs::remove_all(dir);
  return e;
}

// Mesa's EGL without its drivers (eglInitialize fails on every display), and glvnd without any
// EGL vendor (no display at all): EGL forced is one line naming what failed; auto falls back to
// OSMesa and says why.
TEST(RendererProcess, AnEglThatCannotRenderIsOneLineAndAutoFallsBack) {
  const std::string no_driver = "LIBGL_DRIVERS_PATH=/nonexistent";
  const std::string no_vendor = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";
  for (const std::string& env : {no_driver, no_vendor}) {
    SCOPED_TRACE(env);
    const Ended forced = run_pipeserver(env, "--renderer egl --scene swap");
    EXPECT_EQ(forced.code, 1) << forced.output;
    EXPECT_EQ(
        forced.output.rfind("pipeserver: --renderer egl: no EGL display can render here: ", 0), 0u)
        << forced.output;
    EXPECT_EQ(forced.output.find('\n'), forced.output.size() - 1) << forced.output;
    const Ended fallback = run_pipeserver(env, "--scene swap");
    EXPECT_EQ(fallback.code, 0) << fallback.output;
    EXPECT_EQ(fallback.output.rfind("pipeserver 0: renderer osmesa (llvmpipe", 0), 0u)
        << fallback.output;
    EXPECT_NE(fallback.output.find("; auto: no GPU: "), std::string::npos) << fallback.output;
  }
  EXPECT_NE(
      run_pipeserver(no_driver, "--renderer egl")
          .output.find("eglInitialize failed (EGL_NOT_INITIALIZED: DRI2: failed to load driver)"),
      std::string::npos);
  EXPECT_NE(run_pipeserver(no_vendor, "--renderer egl").output.find("EGL finds no driver"),
            std::string::npos);
}

TEST(RendererProcess, AnUnknownRendererIsAUsageError) {
  const Ended e = run_pipeserver("", "--renderer bogus");
  EXPECT_EQ(e.code, 2);
  EXPECT_EQ(e.output.rfind("pipeserver: --renderer: expected egl, osmesa or auto, got bogus\n", 0),
            0u)
      << e.output;
}

}  // namespace
}  // namespace l2
