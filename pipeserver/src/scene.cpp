#include "pipeserver/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "command_line/program_paths.hpp"
#include "scene_common.hpp"

namespace l2 {

void Box::extend(glm::vec3 p) {
  lo = glm::min(lo, p);
  hi = glm::max(hi, p);
}

Box Box::empty() {
  constexpr float inf = std::numeric_limits<float>::infinity();
  return {glm::vec3(inf), glm::vec3(-inf)};
}

std::size_t Batch::triangle_count() const {
  if (primitive == Primitive::Triangles) {
    return (indices.empty() ? positions.size() : indices.size()) / 3;
  }
  std::size_t n = 0;
  for (const int c : strip_count) n += static_cast<std::size_t>(std::max(c - 2, 0));
  return n;
}

void Batch::compute_bounds() {
  bounds = Box::empty();
  for (const auto& p : positions) bounds.extend(p);
}

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& b : batches_) n += b.triangle_count();
  return n;
}

void Scene::set_frame(int frame) {
  frame_ = frame;
  model_ = glm::mat4(1.0f);
  animate(frame);
  const float orbit = camera_.orbit.value_or(default_orbit());
  if (orbit != 0) model_ = orbit_matrix(orbit, frame, centre()) * model_;
}

void Scene::set_camera(const CameraOptions& camera) {
  camera_ = camera;
}

void Scene::place_windows(const std::vector<WindowPlacement>& /*back_to_front*/) {
  throw std::invalid_argument(fmt::format("the {} scene has no windows to place", name()));
}

const std::vector<std::string>& built_in_scene_names() {
  static const std::vector<std::string> names{"mesh",       "strips",  "hotspot",
                                              "isosurface", "patches", "swap"};
  return names;
}

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = built_in_scene_names();
    all.insert(all.end(), {"picture", "movie", "session", "vnc"});
    return all;
  }();
  return names;
}

// Installed beside the walls, or in the working tree (command_line/program_paths.hpp).
std::filesystem::path default_mesh_file() {
  const std::filesystem::path bunny = std::filesystem::path("data") / "bunny.ply";
  return project_files(bunny).value_or(std::filesystem::path()) / bunny;
}

namespace {

std::unique_ptr<Scene> make_named(const std::string& name, const SceneOptions& options) {
  if (name == "mesh") {
    if (options.fit == "stretch")
      throw std::invalid_argument(
          "--fit stretch is for pictures and movies; a model fits or fills");
    const auto path = options.mesh_file.empty() ? default_mesh_file() : options.mesh_file;
    return detail::make_mesh_scene(load_mesh(path), options.fit != "fill");
  }
  if (name == "strips") return detail::make_strips_scene(options);
  if (name == "hotspot") return detail::make_hotspot_scene(options);
  if (name == "isosurface") return detail::make_isosurface_scene(options);
  if (name == "patches") return detail::make_patches_scene(options);
  if (name == "swap") return detail::make_swap_scene();
  if (name == "picture" || name == "movie") {
    if (options.content.empty()) {
      throw std::invalid_argument(fmt::format("--scene {} needs --content FILE", name));
    }
    const std::optional<SourceFit> fit = parse_source_fit(options.fit);
    if (!options.fit.empty() && !fit)
      throw std::invalid_argument("--fit: expected fit, fill or stretch, got " + options.fit);
    if (name == "picture") {
      std::optional<FixedView> fixed;
      if (!options.pan.empty() || options.zoom > 0) fixed = FixedView{{}, {}, options.zoom};
      if (!options.pan.empty() && !parse_pan(options.pan, *fixed))
        throw std::invalid_argument("--pan: expected X,Y, two numbers, got " + options.pan);
      return detail::make_picture_scene(options.content, fit.value_or(SourceFit::Fill),
                                        options.picture_cache_mb, false, fixed);
    }
    return detail::make_movie_scene(options.content, options.movie_rate,
                                    fit.value_or(SourceFit::Fit));
  }
  if (name == "session") {
    if (options.session.empty())
      throw std::invalid_argument("--scene session needs --session FILE");
    return detail::make_session_scene(options.session, options);
  }
  if (name == "vnc") {
    if (options.content.empty())
      throw std::invalid_argument("--scene vnc needs --content HOST:DISPLAY");
    return detail::make_vnc_scene(options.content.string());
  }
  throw std::invalid_argument(
      fmt::format("unknown scene '{}' (expected mesh, strips, hotspot, isosurface, patches, swap, "
                  "picture, movie, session or vnc)",
                  name));
}

std::function<std::unique_ptr<Scene>()>& replacement() {
  static std::function<std::unique_ptr<Scene>()> make;
  return make;
}

}  // namespace

void replace_scenes(std::function<std::unique_ptr<Scene>()> make) {
  replacement() = std::move(make);
}

std::unique_ptr<Scene> make_scene(const std::string& name, const SceneOptions& options) {
  auto scene = replacement() ? replacement()() : make_named(name, options);
  scene->set_camera(options.camera);
  scene->set_frame(0);
  return scene;
}

}  // namespace l2
