// Your own pipeserver: a program whose main() calls run_renderer() with a function that draws
// one tile with OpenGL (TileView in scene.hpp says what it is given), through l2::gl() — the
// GL functions of the renderer the pipeserver decided on (--renderer: OSMesa or EGL, on a GPU
// where there is one; gl_api.hpp). Plain gl* symbols are no renderer's: the library loads
// libOSMesa by name, and EGL's functions are each context's own. The library does the rest,
// as for `pipeserver` itself: the wall file, the packing of tiles into the framebuffer, the strip
// headers with the frame's parity, the scan-out into the DVI link or to the compositing server,
// READY on the back-channel, and pipeserver's whole command line, so that
// `l2wall run --pipeserver-program YOUR_PROGRAM` drives it as it drives pipeserver (README.md,
// "Your own renderer").
#pragma once

#include <functional>
#include <memory>

#include "pipeserver/gl_api.hpp"
#include "pipeserver/scene.hpp"

namespace l2 {

// Called for every tile of every frame. It must draw the same scene for the same frame on every
// pipeserver (a pure function of view.frame), as the built-in scenes do, or the tiles of one
// frame will not match at their edges.
using DrawTile = std::function<void(const TileView& view)>;

// `pipeserver`'s command line and behaviour with every scene replaced by `draw`'s (--scene and
// the scene options are accepted, so l2wall's pipeservers start alike, and draw nothing of their
// own). Returns the exit status for main().
int run_renderer(int argc, char** argv, DrawTile draw);

// The scene run_renderer() shows: for a program's own tests (render_reference, Pipeserver).
std::unique_ptr<Scene> make_own_scene(DrawTile draw);

// `pipeserver` itself: the built-in scenes.
int run_pipeserver(int argc, char** argv);

}  // namespace l2
