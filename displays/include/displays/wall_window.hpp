// --show window: one window laying out the whole wall as the wall file places it, scaled down
// only if it does not fit the screen, mullions as dark bars, and an overlay line below the wall
// ("frame 12  59.8 fps  latency 1 frame"). The overlay sits in its own bar, never over pixels.
#pragma once

#include <memory>

#include "displays/wall_presenter.hpp"
#include "displays/wall_view.hpp"

namespace l2 {

class GlfwSession;
class GlWindow;

class WallWindow final : public WallPresenter {
 public:
  static constexpr int kOverlayHeight = 22;
  // Room left for a window manager's title bar and panels when sizing the window.
  static constexpr int kDecorationAllowance = 48;

  WallWindow(const Wall& wall, const PresenterOptions& options);  // throws DisplayError
  ~WallWindow() override;

  void present(const FrameInfo& info, const std::vector<RgbImage>& displays) override;
  UserAction poll_events() override;
  std::vector<RgbImage> read_back() override;
  std::vector<RgbImage> read_back_windows() override;

  // Where the displays are in the window as last presented (at first: as opened).
  const WallView& view() const { return view_; }

 private:
  Wall wall_;
  std::unique_ptr<GlfwSession> session_;
  std::unique_ptr<GlWindow> window_;
  WallView view_;
};

}  // namespace l2
