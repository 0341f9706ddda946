#include "image/picture_regions.hpp"

#include <stdexcept>
#include <string>

#include "png_codec.hpp"

namespace l2 {

PictureRegions::PictureRegions(const std::filesystem::path& path) : path_(path) {
  auto opened = png_codec::codec(path).open_regions(path.c_str());
  if (!opened.ok()) throw std::runtime_error(path.string() + ": " + opened.reason());
  reader_ = std::move(opened).value();
  width_ = reader_->width();
  height_ = reader_->height();
}

PictureRegions::~PictureRegions() = default;

void PictureRegions::read_row(int y, int x_begin, int x_end, std::uint8_t* rgb) const {
  if (y < 0 || y >= height_ || x_begin < 0 || x_end > width_ || x_begin >= x_end) {
    throw std::out_of_range(path_.string() + ": row " + std::to_string(y) + " columns " +
                            std::to_string(x_begin) + ".." + std::to_string(x_end) +
                            " lie outside the picture");
  }
  const Status read = reader_->read_row(y, x_begin, x_end, rgb);
  if (!read.ok()) throw std::runtime_error(path_.string() + ": " + read.reason());
}

}  // namespace l2
