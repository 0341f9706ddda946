#include "displays/wall_presenter.hpp"

#include <fmt/format.h>

#include "displays/monitor_wall.hpp"
#include "displays/wall_window.hpp"
#include "image/png_io.hpp"

namespace l2 {

std::unique_ptr<WallPresenter> open_presenter(ShowMode mode, const Wall& wall,
                                              const PresenterOptions& options) {
  if (mode == ShowMode::Monitors) return std::make_unique<MonitorWall>(wall, options);
  return std::make_unique<WallWindow>(wall, options);
}

std::optional<ShowMode> parse_show_mode(std::string_view text) {
  if (text == "window") return ShowMode::Window;
  if (text == "monitors") return ShowMode::Monitors;
  return std::nullopt;
}

std::vector<std::filesystem::path> save_screenshots(WallPresenter& presenter,
                                                    const std::filesystem::path& dir,
                                                    const std::string& prefix) {
  std::vector<std::filesystem::path> written;
  const std::vector<RgbImage> displays = presenter.read_back();
  for (std::size_t d = 0; d < displays.size(); ++d) {
    written.push_back(dir / fmt::format("{}display-{}.png", prefix, d));
    write_png(written.back(), displays[d]);
  }
  const std::vector<RgbImage> windows = presenter.read_back_windows();
  for (std::size_t i = 0; i < windows.size(); ++i) {
    written.push_back(dir / fmt::format("{}window-{}.png", prefix, i));
    write_png(written.back(), windows[i]);
  }
  return written;
}

}  // namespace l2
