// `session`: the windows of a session file (session_file.hpp), each a scene of its own drawn
// into its canvas rectangle as if that were its whole canvas (tile_renderer.cpp), back to
// front over the background colour. Pictures stay still in their window, laid as its fit says.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "scene_common.hpp"
#include "scene_vnc.hpp"
#include "tilelayout/session_file.hpp"

namespace l2::detail {

namespace {

glm::vec3 colour_of(std::uint32_t rgb) {
  return glm::vec3(static_cast<float>(rgb >> 16 & 0xFF), static_cast<float>(rgb >> 8 & 0xFF),
                   static_cast<float>(rgb & 0xFF)) /
         255.0f;
}

// The window's source, made as the scene of that name with the run's options but the window's
// file and fit. Only a picture is made apart: still, where the picture scene pans and zooms;
// and a desktop, which draws from the session's desktop of its address.
std::unique_ptr<Scene> make_source(const SessionWindow& w, const SceneOptions& run,
                                   const DesktopScene* desktop) {
  SceneOptions o = run;
  o.fit = w.fit;
  if (desktop)
    return make_desktop_window(*desktop, parse_source_fit(w.fit).value_or(SourceFit::Fit));
  if (w.source == "picture") {
    auto scene = make_picture_scene(w.content, parse_source_fit(w.fit).value_or(SourceFit::Fit),
                                    o.picture_cache_mb, true);
    scene->set_camera(o.camera);
    scene->set_frame(0);
    return scene;
  }
  if (w.source == "mesh") o.mesh_file = w.content;
  if (w.source == "movie") o.content = w.content;
  return make_scene(w.source, o);
}

class SessionScene : public Scene {
 public:
  SessionScene(const Session& session, const SceneOptions& options) : session_(session) {
    lit_ = false;
    clear_colour_ = colour_of(session.background);
    for (const SessionWindow& w : session.windows) {
      placed_.push_back({sources_.size(), w.on_canvas});
      sources_.push_back(make_source(w, options, desktop_of(w)));
      // What a window's model leaves out is told once for the session, naming the window.
      if (!sources_.back()->note().empty()) {
        if (!note_.empty()) note_ += "; ";
        note_ += fmt::format("window {}: {}", w.id, sources_.back()->note());
      }
    }
    add_shares();
  }
  const char* name() const override { return "session"; }

  std::vector<SceneWindow> windows() const override {
    std::vector<SceneWindow> out;
    for (const Placed& p : placed_) out.push_back({p.on_canvas, sources_[p.source].get()});
    return out;
  }

  std::vector<DesktopScene*> desktops() override {
    std::vector<DesktopScene*> out;
    for (const auto& d : desktops_) out.push_back(d.scene.get());
    return out;
  }

  void place_windows(const std::vector<WindowPlacement>& back_to_front) override {
    std::vector<Placed> placed;
    for (const WindowPlacement& w : back_to_front) {
      const auto at = std::find_if(session_.windows.begin(), session_.windows.end(),
                                   [&w](const SessionWindow& s) { return s.id == w.id; });
      if (at == session_.windows.end())
        throw std::invalid_argument(fmt::format("the session has no window {}", w.id));
      placed.push_back({static_cast<std::size_t>(at - session_.windows.begin()), w.on_canvas});
    }
    placed_ = std::move(placed);
  }

 protected:
  void animate(int frame) override {
    for (auto& s : sources_) s->set_frame(frame);
  }

 private:
  // A window shown: its source and where it is now.
  struct Placed {
    std::size_t source = 0;  // into sources_
    Rect on_canvas;
  };

  // A vnc window's desktop: one per address and password file, as the coordinator connects.
  const DesktopScene* desktop_of(const SessionWindow& w) {
    if (w.source != "vnc") return nullptr;
    const auto key = std::pair{w.content, w.password_file};
    for (const auto& d : desktops_)
      if (d.key == key) return d.scene.get();
    desktops_.push_back({key, std::make_unique<DesktopScene>(w.content.string())});
    return desktops_.back().scene.get();
  }

  // The screens shared from the control page (`shares`): each a desktop of its own, after the
  // vnc desktops (the coordinator answers in that order), and a window shown only while the
  // coordinator's WINDOWS line names it.
  void add_shares() {
    const int first = share_window_id(session_, 0);  // before the shares' windows join
    for (int k = 0; k < session_.shares; ++k) {
      SessionWindow w;
      w.id = first + k;
      w.source = "share";
      auto scene = std::make_unique<DesktopScene>(fmt::format("share {}", w.id));
      sources_.push_back(make_desktop_window(*scene, SourceFit::Fit));
      desktops_.push_back({{fmt::format("share {}", w.id), {}}, std::move(scene)});
      session_.windows.push_back(std::move(w));
    }
  }

  struct Desktop {
    std::pair<std::filesystem::path, std::filesystem::path> key;  // address, password file
    std::unique_ptr<DesktopScene> scene;
  };

  Session session_;
  std::vector<Desktop> desktops_;                // before sources_, which draw from them
  std::vector<std::unique_ptr<Scene>> sources_;  // by session_.windows index
  std::vector<Placed> placed_;                   // back to front
};

}  // namespace

std::unique_ptr<Scene> make_session_scene(const std::filesystem::path& file,
                                          const SceneOptions& options) {
  return std::make_unique<SessionScene>(load_session(file), options);
}

}  // namespace l2::detail
