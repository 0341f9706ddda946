#include "pipeserver/tile_renderer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

#include "draw_rgb.hpp"
#include "pipeserver/gl_api.hpp"

namespace l2 {

namespace {

void clear_framebuffer() {
  gl().Disable(GL_SCISSOR_TEST);
  gl().ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  gl().ClearDepth(1.0);
  gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// Set for every tile, not once a frame: a session's windows draw scenes lit and unlit into one
// framebuffer, each tile of each window in its own scene's state.
void setup_state(bool lit) {
  gl().Enable(GL_DEPTH_TEST);
  gl().DepthFunc(GL_LESS);
  gl().Disable(GL_CULL_FACE);
  gl().Disable(GL_DITHER);  // dithering depends on window position, so it would differ per tile
  gl().ShadeModel(GL_SMOOTH);
  // Textures only while a textured batch draws (draw_batch): a picture tile's glDrawPixels
  // would be textured too.
  gl().Disable(GL_TEXTURE_2D);
  gl().DisableClientState(GL_TEXTURE_COORD_ARRAY);
  gl().TexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);  // texel x lit colour
  gl().EnableClientState(GL_VERTEX_ARRAY);
  gl().EnableClientState(GL_COLOR_ARRAY);
  if (!lit) {
    gl().Disable(GL_LIGHTING);
    gl().DisableClientState(GL_NORMAL_ARRAY);
    return;
  }
  gl().EnableClientState(GL_NORMAL_ARRAY);
  gl().Enable(GL_LIGHTING);
  gl().Enable(GL_LIGHT0);
  gl().Enable(GL_NORMALIZE);
  gl().Enable(GL_COLOR_MATERIAL);
  gl().ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  // A directional key light from upper left, fixed in eye space (so set with identity modelview).
  gl().MatrixMode(GL_MODELVIEW);
  gl().LoadIdentity();
  const GLfloat direction[] = {-0.4f, 0.6f, 1.0f, 0.0f};
  const GLfloat ambient[] = {0.25f, 0.25f, 0.25f, 1.0f};
  const GLfloat diffuse[] = {0.85f, 0.85f, 0.85f, 1.0f};
  const GLfloat none[] = {0.0f, 0.0f, 0.0f, 1.0f};
  gl().Lightfv(GL_LIGHT0, GL_POSITION, direction);
  gl().Lightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  gl().Lightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  gl().Lightfv(GL_LIGHT0, GL_SPECULAR, none);
  gl().LightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  gl().LightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
}

// Binds a model's texture, giving it to the current context first if it has not got it: its id
// is its GL name in every context (model_texture.hpp). Sampled nearest, without mipmaps, as the
// picture scene samples its picture: every pixel is one texel times the lit colour. A tile,
// drawn as its display's window draws it, takes the same texel as the display's reference.
void bind(const ModelTexture& texture) {
  const bool given = gl().IsTexture(texture.id) == GL_TRUE;
  gl().BindTexture(GL_TEXTURE_2D, texture.id);
  if (given) return;
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  gl().TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  gl().PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Row 0 of the picture, its top, is GL's t = 0: TriangleMesh::uvs count v from the top.
  gl().TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, texture.image.width(), texture.image.height(), 0,
                  GL_RGB, GL_UNSIGNED_BYTE, texture.image.data());
}

// Triangles of a triangle batch, strips of a strip batch: the units a share is cut in.
std::size_t primitives(const Batch& b) {
  if (b.primitive == Primitive::TriangleStrips) return b.strip_first.size();
  return (b.indices.empty() ? b.positions.size() : b.indices.size()) / 3;
}

}  // namespace

TileRenderer::TileRenderer(const Scene& scene, const Canvas& canvas, GeometryShare share,
                           const StereoEye& eye)
    : TileRenderer(scene, canvas, share, eye, true) {}

TileRenderer::TileRenderer(const Scene& scene, const Canvas& canvas, GeometryShare share,
                           const StereoEye& eye, bool clear)
    : scene_(scene),
      canvas_(canvas),
      camera_(eye_camera(
          frame_sphere(canvas, scene.centre(), scene.radius(), scene.camera(), scene.seen_whole()),
          eye, scene.centre())),
      drawn_(scene.batches().size(), false) {
  if (clear) clear_framebuffer();
  const glm::mat4 clip_from_model = camera_.projection * camera_.view * scene.model();
  footprints_.reserve(scene.batches().size());
  for (const auto& b : scene.batches()) {
    footprints_.push_back(canvas_footprint(canvas, clip_from_model, b.bounds));
  }
  make_windows(share, eye);

  std::size_t total = 0;
  for (const auto& b : scene.batches()) total += primitives(b);
  const auto cut = [&](int layer) {
    return total * static_cast<std::size_t>(layer) / static_cast<std::size_t>(share.layers);
  };
  const std::size_t begin = cut(share.layer), end = cut(share.layer + 1);
  std::size_t at = 0;
  for (const auto& b : scene.batches()) {
    const std::size_t lo = std::clamp(begin, at, at + primitives(b));
    const std::size_t hi = std::clamp(end, at, at + primitives(b));
    share_first_.push_back(lo - at);
    share_count_.push_back(hi - lo);
    at += primitives(b);
  }
}

void TileRenderer::make_windows(GeometryShare share, const StereoEye& eye) {
  // A window's scene is drawn apart from the others: its batches split by layer would leave
  // the composite of one layer's window over another's picture meaningless.
  const std::vector<SceneWindow> windows = scene_.windows();
  if (!windows.empty() && share.layers > 1)
    throw std::invalid_argument("a session cannot be drawn on a wall of depth layers");
  for (const SceneWindow& w : windows) {
    const Canvas own{w.on_canvas.w, w.on_canvas.h};
    windows_.push_back({w.on_canvas, std::unique_ptr<TileRenderer>(
                                         new TileRenderer(*w.scene, own, share, eye, false))});
  }
}

BucketStats TileRenderer::stats() const {
  BucketStats all = stats_;
  for (const auto& w : windows_) {
    const BucketStats s = w.renderer->stats();
    all.batches += s.batches;
    all.tile_draws += s.tile_draws;
  }
  return all;
}

Footprints TileRenderer::footprints() const {
  Footprints out;
  const auto& batches = scene_.batches();
  for (std::size_t i = 0; i < batches.size(); ++i) {
    if (share_count_[i] == 0 || footprints_[i].empty()) continue;
    const double share = double(share_count_[i]) / double(primitives(batches[i]));
    out.push_back({footprints_[i], share * double(batches[i].triangle_count())});
  }
  return out;
}

void TileRenderer::draw_tile(const Rect& on_canvas, const Rect& window) {
  draw_tile(on_canvas, window, scene_.clear_colour());
}

void TileRenderer::draw_tile(const Rect& on_canvas, const Rect& window, glm::vec3 clear) {
  draw_tile(on_canvas, window, clear, window);
}

void TileRenderer::draw_tile(const Rect& on_canvas, const Rect& window, glm::vec3 clear,
                             const Rect& seen) {
  const bool squeezed = seen != window;
  if (squeezed && !windows_.empty())
    throw std::invalid_argument("a session's windows cannot be squeezed into packed stereo");
  setup_state(scene_.lit());
  gl().Viewport(0, 0, window.w, window.h);
  // GL rows count from the bottom of the window.
  const int gl_x = on_canvas.x - window.x, gl_y = window.bottom() - on_canvas.bottom();
  gl().Scissor(gl_x, gl_y, on_canvas.w, on_canvas.h);
  gl().Enable(GL_SCISSOR_TEST);
  // Only the tile is cleared: the window may hold tiles of another display from before, and
  // in a framebuffer the rest must stay black (the mesh would read colour there as headers).
  gl().ClearColor(clear.r, clear.g, clear.b, 1.0f);
  gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (scene_.fill_tile(canvas_, on_canvas, pixels_)) {
    if (squeezed)
      throw std::invalid_argument(
          fmt::format("a {} scene's pixels cannot be squeezed into packed stereo", scene_.name()));
    detail::draw_rgb(pixels_, gl_x, gl_y);
  }
  gl().MatrixMode(GL_PROJECTION);
  const glm::dmat4 to_window = tile_matrix(canvas_, seen);
  gl().LoadMatrixd(glm::value_ptr(to_window * glm::dmat4(camera_.projection)));
  gl().MatrixMode(GL_MODELVIEW);
  gl().LoadMatrixf(glm::value_ptr(camera_.view * scene_.model()));
  scene_.draw_tile({canvas_, on_canvas, scene_.frame(), to_window, camera_});
  // Footprints are on the canvas the camera frames: a squeezed tile is compared by what it shows.
  const Rect shows = squeezed
                         ? Rect{seen.x + (on_canvas.x - window.x) * seen.w / window.w,
                                seen.y + (on_canvas.y - window.y) * seen.h / window.h,
                                on_canvas.w * seen.w / window.w, on_canvas.h * seen.h / window.h}
                         : on_canvas;
  const auto& batches = scene_.batches();
  for (std::size_t i = 0; i < batches.size(); ++i) {
    if (share_count_[i] == 0 || !overlaps(footprints_[i], shows)) continue;
    draw_batch(batches[i], share_first_[i], share_count_[i]);
    ++stats_.tile_draws;
    if (!drawn_[i]) {
      drawn_[i] = true;
      ++stats_.batches;
    }
  }
  draw_windows(on_canvas, window);
}

void TileRenderer::draw_windows(const Rect& on_canvas, const Rect& window) {
  // Each window sees the canvas from its own top-left corner: the tile's part of it and the GL
  // window, moved by the same whole pixels, keep every pixel where it was.
  for (const auto& w : windows_) {
    const Rect part = intersect(on_canvas, w.on_canvas);
    if (part.empty()) continue;
    const auto moved = [&w](Rect r) {
      return Rect{r.x - w.on_canvas.x, r.y - w.on_canvas.y, r.w, r.h};
    };
    w.renderer->draw_tile(moved(part), moved(window));
  }
}

void TileRenderer::draw_batch(const Batch& b, std::size_t first, std::size_t count) const {
  if (b.texture) {
    bind(*b.texture);
    gl().Enable(GL_TEXTURE_2D);
    gl().EnableClientState(GL_TEXTURE_COORD_ARRAY);
    gl().TexCoordPointer(2, GL_FLOAT, 0, b.uvs.data());
  }
  draw_primitives(b, first, count);
  if (b.texture) {
    gl().Disable(GL_TEXTURE_2D);
    gl().DisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
}

void TileRenderer::draw_primitives(const Batch& b, std::size_t first, std::size_t count) const {
  gl().VertexPointer(3, GL_FLOAT, 0, b.positions.data());
  gl().ColorPointer(3, GL_FLOAT, 0, b.colours.data());
  if (scene_.lit()) gl().NormalPointer(GL_FLOAT, 0, b.normals.data());
  if (b.primitive == Primitive::TriangleStrips) {
    gl().MultiDrawArrays(GL_TRIANGLE_STRIP, b.strip_first.data() + first,
                         b.strip_count.data() + first, static_cast<GLsizei>(count));
  } else if (b.indices.empty()) {
    gl().DrawArrays(GL_TRIANGLES, static_cast<GLint>(first * 3), static_cast<GLsizei>(count * 3));
  } else {
    gl().DrawElements(GL_TRIANGLES, static_cast<GLsizei>(count * 3), GL_UNSIGNED_INT,
                      b.indices.data() + first * 3);
  }
}

}  // namespace l2
