// Scenes a pipeserver renders: geometry in batches, each with a bounding box so sort-first
// bucketing can skip the tiles a batch does not touch. Every scene is a pure function of its
// options and the frame number, so all pipeservers of a wall (and the reference render) agree.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/rgb_image.hpp"
#include "pipeserver/camera.hpp"
#include "pipeserver/model_texture.hpp"

namespace l2 {

struct Box {
  glm::vec3 lo{0.0f}, hi{0.0f};
  void extend(glm::vec3 p);
  static Box empty();
};

enum class Primitive { Triangles, TriangleStrips };

// One draw call's worth of geometry, in the scene's model space.
struct Batch {
  Primitive primitive = Primitive::Triangles;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;             // empty when the scene is unlit
  std::vector<glm::vec3> colours;             // per vertex, 0..1
  std::vector<std::uint32_t> indices;         // Triangles: indexed; empty means positions in order
  std::vector<int> strip_first, strip_count;  // TriangleStrips: one entry per strip
  // A model's base-colour texture, multiplied into the colours; with it, per vertex, where the
  // vertex is on it (model_file.hpp's TriangleMesh::uvs). Null: the colours alone.
  std::shared_ptr<const ModelTexture> texture;
  std::vector<glm::vec2> uvs;
  Box bounds;

  std::size_t triangle_count() const;
  void compute_bounds();
};

// The most triangles a generated scene (strips, patches) may ask for.
inline constexpr long kMaxTriangles = 50'000'000;

struct SceneOptions {
  std::filesystem::path mesh_file;  // mesh: any model file Assimp reads; empty: the bunny
  long triangles = 100000;          // strips: total triangle count (up to millions)
  int strip_length = 16;            // strips: triangles per strip
  int grid = 40;                    // isosurface: cells along each axis
  int tessellation = 16;            // patches: segments along each patch edge
  int patches = 4;                  // patches: patches along each side of the sheet
  std::filesystem::path content;    // picture, movie: the file shown
  // movie: application frames per second the movie's clock runs at (application frame k shows
  // the movie at k / movie_rate seconds); 0: movie frame k is application frame k.
  double movie_rate = 0;
  // picture, movie: how the source is laid on the canvas, "fit", "fill" or "stretch"
  // (picture_view.hpp); mesh: "fit" (the whole model in view) or "fill" (a wide wall spanned,
  // the model cropped across it); empty: the scene's own (picture: fill, movie and mesh: fit).
  std::string fit;
  std::filesystem::path session;  // session: the session file (session_file.hpp)
  // picture, session: the most MiB of decoded picture each picture's image cache holds
  // (picture_cache.hpp); 0: default_picture_cache_mb for this machine and one pipeserver.
  double picture_cache_mb = 0;
  // picture: a fixed view instead of the animated path, "X,Y" (picture pixel at the canvas's
  // centre) and canvas pixels per picture pixel (picture_view.hpp's FixedView); empty and 0:
  // not given.
  std::string pan;
  double zoom = 0;
  CameraOptions camera;  // every scene
};

class Scene;
namespace detail {
class DesktopScene;  // scene_vnc.hpp
}

// One window of a session: a scene drawn into a rectangle of the canvas as if that rectangle
// were its whole canvas, over what is behind it.
struct SceneWindow {
  Rect on_canvas;
  const Scene* scene = nullptr;
};

// Where a session's window (by its id in the session file) is to be drawn.
struct WindowPlacement {
  int id = 0;
  Rect on_canvas;
};

// What a program's own drawing (renderer.hpp) is given for each tile. When it is called, the
// tile's viewport and scissor are set, GL_PROJECTION holds tile * camera.projection and
// GL_MODELVIEW camera.view (turned by --camera-orbit, when given), so drawing the whole scene,
// inside the unit sphere about the origin, draws the tile's part of it; the tile has been cleared
// to black, colour and depth.
struct TileView {
  Canvas canvas;
  Rect on_canvas;        // the tile's rectangle on the canvas (rows top to bottom)
  int frame = 0;         // the application frame: every pipeserver draws the same scene for it
  glm::dmat4 tile{1.0};  // takes the whole canvas's clip space to the GL window's (the tile's
                         // display, or the tile alone; the scissor keeps drawing inside the tile)
  Camera camera;         // the wall's camera, the unit sphere framed on the canvas
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual const char* name() const = 0;
  // Makes batches() and model() those of frame `frame`, the camera's orbit included. Same
  // frame, same geometry.
  void set_frame(int frame);
  int frame() const { return frame_; }
  const CameraOptions& camera() const { return camera_; }
  // An orbit left unset is the scene's default_orbit().
  void set_camera(const CameraOptions& camera);

  const std::vector<Batch>& batches() const { return batches_; }
  const glm::mat4& model() const { return model_; }
  bool lit() const { return lit_; }
  // What every tile (not the rest of the framebuffer) is cleared to before the batches are
  // drawn (0..1 per channel).
  glm::vec3 clear_colour() const { return clear_colour_; }
  // The sphere every frame of the scene stays inside (model transform applied): the camera
  // frames it, so it must not depend on the frame.
  glm::vec3 centre() const { return {0.0f, 0.0f, 0.0f}; }
  float radius() const { return 1.0f; }
  // Whether the camera shows the whole sphere on any canvas (frame_sphere's `whole`): a model
  // is seen whole on a wide wall unless told to fill it (--fit); the generated scenes fill it.
  virtual bool seen_whole() const { return false; }

  std::size_t triangle_count() const;
  // A line about the scene's file worth telling once, not an error: what of a model file was
  // left out (TriangleMesh::left_out). Empty: nothing to tell.
  const std::string& note() const { return note_; }

  // A scene of pixels rather than geometry (picture, movie) fills each tile with them: `rgb`
  // becomes the tile's size, rows top to bottom, and is drawn over the cleared tile. false: the
  // scene has batches only.
  virtual bool fill_tile(const Canvas& /*canvas*/, const Rect& /*on_canvas*/,
                         RgbImage& /*rgb*/) const {
    return false;
  }
  // A program's own scene (renderer.hpp) draws each tile itself (it has no batches).
  virtual void draw_tile(const TileView& /*view*/) const {}
  // A session's windows, back to front, drawn over the tile after its clear to clear_colour():
  // the scene itself has no batches and no pixels. Empty for every other scene.
  virtual std::vector<SceneWindow> windows() const { return {}; }
  // A session's windows from now on, back to front (moved, resized, raised; one not listed is
  // closed): the coordinator's WINDOWS line, the same on every pipeserver. Throws
  // std::invalid_argument for a window the session does not have, or when this is no session.
  virtual void place_windows(const std::vector<WindowPlacement>& back_to_front);
  // The desktops the scene shows, whose pixels the run's coordinator sends each frame
  // (docs/vnc.md): the vnc scene's, or those of a session's vnc windows, one per address, in
  // the order of the session's windows (back to front). Empty for every other scene.
  virtual std::vector<detail::DesktopScene*> desktops() { return {}; }

 protected:
  // The scene's own animation: batches_ and model_ of frame `frame`.
  virtual void animate(int frame) = 0;
  virtual float default_orbit() const { return 0; }

  std::vector<Batch> batches_;
  std::string note_;
  glm::mat4 model_{1.0f};
  bool lit_ = true;
  glm::vec3 clear_colour_{0.0f};

 private:
  CameraOptions camera_;
  int frame_ = 0;
};

// "mesh", "strips", "isosurface", "patches", "swap" (no geometry: frame k is cleared to
// ((64 + 37k) mod 256, (128 + 101k) mod 256, (192 + 173k) mod 256) as 8-bit RGB), "picture"
// (options.content, any format OpenImageIO reads, panned and zoomed: picture_view.hpp) or
// "movie" (options.content, any format FFmpeg reads, fitted to the canvas) or "session"
// (options.session: windows of those, session_file.hpp). Throws
// std::invalid_argument on an unknown name or a picture or movie without a file, and
// std::runtime_error (naming the file, and the line where there is one) on an unreadable mesh,
// picture or movie.
std::unique_ptr<Scene> make_scene(const std::string& name, const SceneOptions& options = {});
// From now on make_scene() makes `make`'s scene, whatever the name: a program with its own
// drawing (renderer.hpp) shows it on every path of the pipeserver. An empty `make` undoes it.
void replace_scenes(std::function<std::unique_ptr<Scene>()> make);
const std::vector<std::string>& scene_names();
// The scenes that need no file (every one but picture and movie): what a golden entry, a tool
// sweeping every scene or a test over every wall may name.
const std::vector<std::string>& built_in_scene_names();

// The bunny shipped in data/, found relative to the source tree at build time.
std::filesystem::path default_mesh_file();

}  // namespace l2
