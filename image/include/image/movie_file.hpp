// A movie of any format FFmpeg's libraries read, its video frames decoded in order into 8-bit
// RGB; frame k of a movie of n frames is frame k mod n, so a short movie loops.
#pragma once

#include <filesystem>
#include <memory>

#include "image/rgb_image.hpp"

namespace l2 {

namespace png_codec {
class MovieDecoder;
}

class MovieFile {
 public:
  // Throws std::runtime_error naming the file and why, in one line, when it is missing,
  // damaged, not a movie, has no video stream, or frames with a side over kMaxPictureSide.
  explicit MovieFile(const std::filesystem::path& path);
  ~MovieFile();
  MovieFile(const MovieFile&) = delete;
  MovieFile& operator=(const MovieFile&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Frames per second by the movie's own clock; 0 when its container does not say.
  double frames_per_second() const;

  // Frame k (from 0): decoded on from the frame last asked for, from the start again when k
  // lies before it. Throws std::runtime_error naming the file when a frame cannot be decoded,
  // or when the movie holds no frame at all.
  const RgbImage& frame(long k);

 private:
  void reopen();
  bool decode_next();  // false at the end of the stream

  std::filesystem::path path_;
  std::unique_ptr<png_codec::MovieDecoder> decoder_;
  int width_ = 0, height_ = 0;
  RgbImage frame_;
  long decoded_ = -1;      // the frame in frame_; -1: none since the last start
  long frame_count_ = -1;  // known once the end was reached
};

}  // namespace l2
