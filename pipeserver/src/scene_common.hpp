// Pieces the scene implementations share: a seeded random source and the scene classes.
#pragma once

#include <cstdint>
#include <optional>

#include "pipeserver/model_file.hpp"
#include "pipeserver/picture_view.hpp"
#include "pipeserver/scene.hpp"

namespace l2::detail {

// splitmix64: a tiny, well-mixed generator; the same seed gives the same scene everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi).
  float uniform(float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(next() >> 40) / static_cast<float>(1 << 24);
  }

 private:
  std::uint64_t state_;
};

// `whole`: the model seen whole on any canvas (--fit fit), else a wide wall spanned (fill).
std::unique_ptr<Scene> make_mesh_scene(const TriangleMesh& mesh, bool whole);
std::unique_ptr<Scene> make_strips_scene(const SceneOptions& options);
std::unique_ptr<Scene> make_hotspot_scene(const SceneOptions& options);
std::unique_ptr<Scene> make_isosurface_scene(const SceneOptions& options);
std::unique_ptr<Scene> make_patches_scene(const SceneOptions& options);
std::unique_ptr<Scene> make_swap_scene();
// `still`: laid as `fit` says at every frame (a session's window), not panned and zoomed.
// `cache_mb`: the picture's image cache's limit (SceneOptions::picture_cache_mb, 0: the
// machine's default).
// `fixed`: a fixed view (picture_view.hpp) instead of the animated path.
std::unique_ptr<Scene> make_picture_scene(const std::filesystem::path& file, SourceFit fit,
                                          double cache_mb, bool still = false,
                                          std::optional<FixedView> fixed = {});
// A session (session_file.hpp): every window's source drawn into its rectangle, over the
// background; `options` are the run's, for the sources (camera, movie rate, ...).
std::unique_ptr<Scene> make_session_scene(const std::filesystem::path& file,
                                          const SceneOptions& options);
std::unique_ptr<Scene> make_movie_scene(const std::filesystem::path& file, double rate,
                                        SourceFit fit);

// A desktop the run's coordinator sends (scene_vnc.hpp); `address`: HOST:DISPLAY, for messages.
std::unique_ptr<Scene> make_vnc_scene(const std::string& address);

}  // namespace l2::detail
