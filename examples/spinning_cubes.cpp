// A pipeserver of your own: a ring of eight cubes turning about the wall's vertical axis, drawn
// with OpenGL through l2::gl(), the GL functions of the renderer the pipeserver decided on
// (--renderer: OSMesa or EGL; gl_api.hpp). run_renderer() does everything else (renderer.hpp);
// this program takes pipeserver's command line, so `l2wall run --pipeserver-program
// spinning_cubes` drives it.
#include "pipeserver/renderer.hpp"

namespace {

// A cube of side 2 * h about the origin, each face its own shade of the cube's colour.
void draw_cube(float h, float r, float g, float b) {
  static const float faces[6][4][3] = {
      {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
      {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}},
      {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
      {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
      {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
      {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
  };
  const l2::GlApi& gl = l2::gl();
  gl.Begin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    const float shade = 0.5f + 0.1f * static_cast<float>(f);
    gl.Color3f(r * shade, g * shade, b * shade);
    for (const auto& v : faces[f]) gl.Vertex3f(v[0] * h, v[1] * h, v[2] * h);
  }
  gl.End();
}

// The whole scene for one frame, inside the unit sphere; the library has set the tile's
// projection, viewport and scissor, so this is all a tile needs. It puts the matrices back after
// each tile, so the turns need not be undone here.
void draw(const l2::TileView& view) {
  const l2::GlApi& gl = l2::gl();
  const float turn = 2.0f * static_cast<float>(view.frame);  // degrees
  gl.Rotatef(25.0f, 1, 0, 0);                                // the ring seen from a little above
  gl.Rotatef(turn, 0, 1, 0);
  for (int i = 0; i < 8; ++i) {
    gl.PushMatrix();
    gl.Rotatef(45.0f * static_cast<float>(i), 0, 1, 0);
    gl.Translatef(0.7f, 0, 0);
    gl.Rotatef(3.0f * turn, 1, 0, 0);
    draw_cube(0.16f, static_cast<float>(i & 1), static_cast<float>((i >> 1) & 1),
              i < 4 ? 1.0f : 0.4f);
    gl.PopMatrix();
  }
}

}  // namespace

int main(int argc, char** argv) {
  return l2::run_renderer(argc, argv, draw);
}
