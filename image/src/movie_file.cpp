#include "image/movie_file.hpp"

#include <stdexcept>
#include <string>

#include "image/png_io.hpp"
#include "png_codec.hpp"

namespace l2 {

MovieFile::MovieFile(const std::filesystem::path& path) : path_(path) {
  reopen();
  width_ = decoder_->width();
  height_ = decoder_->height();
  // A header can claim any size: checked before the frame is allocated.
  if (width_ > kMaxPictureSide || height_ > kMaxPictureSide) {
    throw std::runtime_error(path.string() + ": frames of " + std::to_string(width_) + "x" +
                             std::to_string(height_) + ", over the " +
                             std::to_string(kMaxPictureSide) + " pixels a side allowed");
  }
  frame_ = RgbImage(width_, height_);
}

MovieFile::~MovieFile() = default;

double MovieFile::frames_per_second() const {
  return decoder_->frames_per_second();
}

void MovieFile::reopen() {
  decoder_.reset(nullptr);
  auto opened = png_codec::codec(path_).open_movie(path_.c_str());
  if (!opened.ok()) throw std::runtime_error(path_.string() + ": " + opened.reason());
  decoder_ = std::move(opened).value();
  decoded_ = -1;
}

bool MovieFile::decode_next() {
  const Result<bool> decoded = decoder_->next_frame(frame_.data());
  if (!decoded.ok()) {
    throw std::runtime_error(path_.string() + ": frame " + std::to_string(decoded_ + 1) + ": " +
                             decoded.reason());
  }
  if (!*decoded) return false;
  ++decoded_;
  return true;
}

const RgbImage& MovieFile::frame(long k) {
  if (frame_count_ > 0) k %= frame_count_;
  if (k < decoded_) reopen();
  while (decoded_ < k) {
    if (decode_next()) continue;
    // The end, before frame k: the movie's length is known now, and k lies within it.
    frame_count_ = decoded_ + 1;
    if (frame_count_ == 0) throw std::runtime_error(path_.string() + ": holds no video frames");
    k %= frame_count_;
    if (k < decoded_) reopen();
  }
  return frame_;
}

}  // namespace l2
