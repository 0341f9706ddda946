// Putting the output displays on real screens: the interface the emulator's live mode and
// `l2wall run --show` drive, one frame at a time, from their main thread (GLFW's rule).
//
//   auto shown = open_presenter(ShowMode::Window, wall, {});
//   for (...) {
//     shown->present(info, displays);            // draws every window, swaps each swap group
//     while (auto a = shown->poll_events(); a != UserAction::None) { ... }
//   }
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "displays/overlay.hpp"
#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

enum class UserAction { None, PauseToggled, Screenshot, Quit };
enum class ShowMode { Window, Monitors };

class WallPresenter {
 public:
  virtual ~WallPresenter() = default;

  // Shows one frame. displays[i] is display i of the wall, in its native raster; it is shown as
  // the panel hangs (turned and mirrored back, image/turn.hpp), pixel for pixel wherever the
  // window has room for it. Throws std::invalid_argument when
  // the number of images differs from the wall's displays.
  virtual void present(const FrameInfo& info, const std::vector<RgbImage>& displays) = 0;

  // Handles pending window events and returns the next user action (space: pause toggled,
  // s: screenshot, q / Esc / closing a window: quit), None when there is none left.
  virtual UserAction poll_events() = 0;

  // What the screens show now, read back from the windows' front buffers: one image per display,
  // cropped from its window and turned back into the display's raster (its own size when shown
  // at scale 1).
  virtual std::vector<RgbImage> read_back() = 0;

  // Whole windows as shown (the wall window: displays, mullions and the overlay bar).
  virtual std::vector<RgbImage> read_back_windows() = 0;

  // What the windows cannot show as the wall asks, one line each, for the caller to say once
  // (a panel larger than its monitor is shown scaled down).
  virtual std::vector<std::string> notes() const { return {}; }
};

struct PresenterOptions {
  bool vsync = true;  // swap on vertical blank where the driver offers it
  std::string title = "Lightning-2 wall";
};

// Opens the window(s). Throws DisplayError (one line: no X display, too few monitors, ...).
std::unique_ptr<WallPresenter> open_presenter(ShowMode mode, const Wall& wall,
                                              const PresenterOptions& options);

// "window" or "monitors"; nullopt otherwise.
std::optional<ShowMode> parse_show_mode(std::string_view text);

// Writes read_back() as DIR/<prefix>display-<d>.png and each window as
// DIR/<prefix>window-<i>.png; returns the files written. Throws std::runtime_error naming a file.
std::vector<std::filesystem::path> save_screenshots(WallPresenter& presenter,
                                                    const std::filesystem::path& dir,
                                                    const std::string& prefix);

}  // namespace l2
