// --show monitors: each output display fullscreen on the monitor its wall file entry names
// (`monitor`: GLFW's name for it, or its index). Refused, with the list of monitors GLFW sees,
// when a display has none or there are fewer monitors than displays. Each swap-lock group is
// drawn first and then swapped back to back, so its monitors show the same frame.
#pragma once

#include <memory>
#include <vector>

#include "displays/wall_presenter.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

class GlfwSession;
class GlWindow;

class MonitorWall final : public WallPresenter {
 public:
  MonitorWall(const Wall& wall, const PresenterOptions& options);  // throws DisplayError
  ~MonitorWall() override;

  void present(const FrameInfo& info, const std::vector<RgbImage>& displays) override;
  UserAction poll_events() override;
  std::vector<RgbImage> read_back() override;
  std::vector<RgbImage> read_back_windows() override;
  std::vector<std::string> notes() const override { return notes_; }

 private:
  // A display that its monitor shows scaled down, said once.
  void note_scaled(const Display& d, int width, int height, const std::string& monitor);

  Wall wall_;
  std::unique_ptr<GlfwSession> session_;
  std::vector<std::unique_ptr<GlWindow>> windows_;  // windows_[i] shows display i
  std::vector<std::vector<int>> groups_;
  std::vector<Rect> shown_;  // where each display's image is in its window
  RgbImage turned_;          // a turned display's frame as it hangs, drawn right away
  std::vector<std::string> notes_;
};

}  // namespace l2
