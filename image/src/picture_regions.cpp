#include "image/picture_regions.hpp"

#include <stdexcept>
#include <string>

#include "png_codec.hpp"

namespace l2 {

PictureRegions::PictureRegions(const std::filesystem::path& path, double cache_megabytes)
    : path_(path) {
  auto opened =
      png_codec::codec(path).open_regions(path.c_str(), static_cast<float>(cache_megabytes));
  if (!opened.ok()) throw std::runtime_error(path.string() + ": " + opened.reason());
  reader_ = std::move(opened).value();
  width_ = reader_->width(0);
  height_ = reader_->height(0);
}

PictureRegions::~PictureRegions() = default;

int PictureRegions::levels() const {
  return reader_->levels();
}

int PictureRegions::width(int level) const {
  return reader_->width(level);
}

int PictureRegions::height(int level) const {
  return reader_->height(level);
}

void PictureRegions::read_row(int level, int y, int x_begin, int x_end, std::uint8_t* rgb) const {
  if (level < 0 || level >= levels() || y < 0 || y >= height(level) || x_begin < 0 ||
      x_end > width(level) || x_begin >= x_end) {
    throw std::out_of_range(path_.string() + ": row " + std::to_string(y) + " columns " +
                            std::to_string(x_begin) + ".." + std::to_string(x_end) +
                            " of MIP level " + std::to_string(level) + " lie outside the picture");
  }
  const Status read = reader_->read_row(level, y, x_begin, x_end, rgb);
  if (!read.ok()) throw std::runtime_error(path_.string() + ": " + read.reason());
}

}  // namespace l2
