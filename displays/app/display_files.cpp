#include "display_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "image/png_io.hpp"

namespace l2 {

namespace {

std::filesystem::path display_file(const std::filesystem::path& dir, int d) {
  return dir / fmt::format("display-{}.png", d);
}

}  // namespace

std::vector<RgbImage> read_display_files(const std::filesystem::path& dir) {
  std::vector<RgbImage> images;
  while (std::filesystem::exists(display_file(dir, static_cast<int>(images.size())))) {
    images.push_back(read_png(display_file(dir, static_cast<int>(images.size()))));
  }
  if (images.empty()) {
    throw std::runtime_error(dir.string() + ": no display-0.png to show");
  }
  return images;
}

std::vector<RgbImage> read_display_files(const std::filesystem::path& dir, const Wall& wall) {
  std::vector<RgbImage> images;
  for (const Display& d : wall.displays) {
    const std::filesystem::path file = display_file(dir, d.id);
    if (!std::filesystem::exists(file)) {
      throw std::runtime_error(file.string() + ": missing (display " + std::to_string(d.id) +
                               " of the wall)");
    }
    images.push_back(read_png(file));
    const RgbImage& image = images.back();
    if (image.width() != d.width || image.height() != d.height) {
      throw std::runtime_error(fmt::format("{}: is {}x{}, but display {} of the wall is {}x{}",
                                           file.string(), image.width(), image.height(), d.id,
                                           d.width, d.height));
    }
  }
  return images;
}

Wall row_wall(const std::vector<RgbImage>& images, int gap) {
  Wall wall;
  wall.name = "displays in a row";
  int x = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    Display d;
    d.id = static_cast<int>(i);
    d.width = images[i].width();
    d.height = images[i].height();
    d.canvas_x = x;
    d.monitor = std::to_string(i);  // monitors in GLFW's order, one per display
    wall.displays.push_back(d);
    x += d.width + gap;
    wall.canvas_height = std::max(wall.canvas_height, d.height);
  }
  wall.canvas_width = std::max(0, x - gap);
  return wall;
}

}  // namespace l2
