// The scene and camera options of `pipeserver` and `l2wall run`: one list, so that l2wall
// checks them as a pipeserver does and passes them on to every pipeserver as typed.
#pragma once

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

#include "command_line/checks.hpp"
#include "pipeserver/picture_view.hpp"
#include "pipeserver/scene.hpp"

namespace l2 {

struct SceneOption {
  CLI::Option* option;
  const char* scene;  // the scenes it belongs to, separated by spaces; nullptr: every scene
};

// Adds --mesh, --content, --fit, --session, --movie-rate, --picture-cache-mb, --pan, --zoom,
// --triangles,
// --strip-length, --grid,
// --tessellation, --patches and the camera's
// --camera-distance, --camera-orbit, --camera-fov to `app`, writing into `o`.
inline std::vector<SceneOption> add_scene_options(CLI::App& app, SceneOptions& o) {
  std::vector<SceneOption> added{
      {app.add_option("--mesh", o.mesh_file,
                      "mesh scene: model file, any format Assimp reads (glTF, OBJ, PLY, STL, FBX, "
                      "...; default: the bunny)")
           ->check(CLI::ExistingFile),
       "mesh"},
      // Checked as a file in check_scene_options: for vnc it is an address.
      {app.add_option("--content", o.content,
                      "picture scene: a picture, any format OpenImageIO reads, of any size; movie "
                      "scene: a movie, any format FFmpeg reads; vnc scene: the desktop's server, "
                      "HOST:DISPLAY (port 5900 + DISPLAY) or HOST::PORT"),
       "picture movie vnc"},
      {app.add_option("--fit", o.fit,
                      "mesh, picture and movie scenes: how the model or source is laid on the "
                      "canvas: fit (all of it in view, dark on two sides of a canvas of another "
                      "shape), fill (the canvas covered, cropped on two sides) or stretch "
                      "(pictures and movies: both axes scaled apart to cover the canvas "
                      "exactly); default: fill for a picture, fit for a model or a movie")
           ->check(CLI::IsMember({"fit", "fill", "stretch"})),
       "mesh picture movie"},
      {app.add_option("--session", o.session,
                      "session scene: a session file, the windows the wall shows "
                      "(docs/session-file.md)")
           ->check(CLI::ExistingFile),
       "session"},
      {app.add_option("--movie-rate", o.movie_rate,
                      "movie scene: application frames per second the movie's clock runs at: "
                      "application frame k shows the movie at k / HZ seconds, movie frames "
                      "dropped or repeated as the rates differ; 0: movie frame k is application "
                      "frame k (exact; l2wall run passes its --refresh, 0 at full speed)")
           ->check(number_in(0, 1000)),
       "movie session"},
      {app.add_option("--picture-cache-mb", o.picture_cache_mb,
                      "picture and session scenes: the most MiB of decoded picture each "
                      "picture's image cache holds (OpenImageIO's max_memory_MB), whatever the "
                      "picture's size; a picture stored as scanlines (PNG, JPEG) larger than it "
                      "is decoded again for the rows the cache let go. Default: a sixteenth of "
                      "the machine's memory, shared among the pipeservers l2wall run starts on "
                      "it (one for a pipeserver alone), at least 512")
           ->check(number_in(1, 100000)),
       "picture session"},
      {app.add_option("--pan", o.pan,
                      "picture scene: a fixed view instead of the animated path, picture pixel "
                      "X,Y (fractions allowed) at the canvas's centre, at every frame; without "
                      "--zoom, at the scale --fit gives")
           ->check(
               [](const std::string& v) {
                 FixedView f;
                 return parse_pan(v, f) ? std::string()
                                        : "expected X,Y, two numbers (picture pixels), got " + v;
               },
               "X,Y"),
       "picture"},
      {app.add_option("--zoom", o.zoom,
                      "picture scene: a fixed view instead of the animated path, Z canvas pixels "
                      "per picture pixel (1: 1:1; 0.25: 4x4 picture pixels a canvas pixel, read "
                      "from a MIP level when the file has them; 2: magnified); without --pan, "
                      "centred on the picture")
           ->check(number_in(1e-6, 1e6)),
       "picture"},
      {app.add_option("--triangles", o.triangles, "strips and hotspot scenes: triangle count")
           ->check(CLI::Range(1L, kMaxTriangles)),
       "strips hotspot"},
      {app.add_option("--strip-length", o.strip_length,
                      "strips and hotspot scenes: triangles per strip")
           ->check(CLI::Range(1, 4096)),
       "strips hotspot"},
      {app.add_option("--grid", o.grid, "isosurface scene: cells per axis")
           ->check(CLI::Range(2, 256)),
       "isosurface"},
      {app.add_option("--tessellation", o.tessellation, "patches scene: segments per patch edge")
           ->check(CLI::Range(1, 1024)),
       "patches"},
      {app.add_option("--patches", o.patches, "patches scene: patches per side")
           ->check(CLI::Range(1, 64)),
       "patches"},
      {app.add_option("--camera-distance", o.camera.distance,
                      "camera: eye to the scene's centre in scene radii; 0 frames the scene on "
                      "the wall's canvas")
           ->check(number_in(0, 1000)),
       nullptr},
      {app.add_option_function<float>(
              "--camera-orbit", [&o](float degrees) { o.camera.orbit = degrees; },
              "camera: degrees a frame the view orbits the scene (default: 3 for mesh, 0 for the "
              "scenes that animate themselves)")
           ->check(number_in(-360, 360)),
       nullptr},
      {app.add_option("--camera-fov", o.camera.fov, "camera: vertical field of view in degrees")
           ->check(number_in(1, 170)),
       nullptr},
  };
  return added;
}

// An option of one scene given for another was ignored without a word: refused instead.
// A picture, movie or session scene without its file is refused too, as is a vnc scene
// without its server.
inline void check_scene_options(const std::vector<SceneOption>& options, const std::string& scene) {
  for (const SceneOption& s : options) {
    if (s.option->get_name() == "--content" && s.option->count() == 0 &&
        (scene == "picture" || scene == "movie")) {
      throw CLI::ValidationError(fmt::format("--scene {} needs --content FILE", scene));
    }
    if (s.option->get_name() == "--content" && s.option->count() == 0 && scene == "vnc")
      throw CLI::ValidationError("--scene vnc needs --content HOST:DISPLAY");
    if (s.option->get_name() == "--content" && s.option->count() > 0 && scene != "vnc") {
      std::string file = s.option->results().back();
      if (std::string why = CLI::ExistingFile(file); !why.empty())
        throw CLI::ValidationError("--content", why);
    }
    if (s.option->get_name() == "--session" && s.option->count() == 0 && scene == "session")
      throw CLI::ValidationError("--scene session needs --session FILE");
    if (s.scene == nullptr || s.option->count() == 0) continue;
    std::string scenes = s.scene;
    if ((" " + scenes + " ").find(" " + scene + " ") != std::string::npos) continue;
    // "a b c" as "a, b or c".
    const std::size_t last = scenes.rfind(' ');
    if (last != std::string::npos) scenes.replace(last, 1, " or ");
    for (std::size_t at = scenes.find(' '); at < scenes.rfind(" or ");
         at = scenes.find(' ', at + 2))
      scenes.replace(at, 1, ", ");
    throw CLI::ValidationError(
        fmt::format("{} is an option of --scene {}, not {}", s.option->get_name(), scenes, scene));
  }
}

// The options given, as arguments for a pipeserver: each name with its value as typed.
inline std::vector<std::string> scene_arguments(const std::vector<SceneOption>& options) {
  std::vector<std::string> args;
  for (const SceneOption& s : options) {
    if (s.option->count() == 0) continue;
    args.push_back(s.option->get_name());
    args.push_back(s.option->results().back());
  }
  return args;
}

}  // namespace l2
