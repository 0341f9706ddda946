// A picture of any format OpenImageIO reads, far larger than memory if need be, read a row's
// part at a time through an image cache of bounded size: a pipeserver showing part of a
// 16k x 16k picture holds the tiles under that part, not the picture. A file with MIP levels (a
// tiled TIFF pyramid, an OpenEXR with levels, a .tx from maketx) is read at whichever level the
// caller asks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

namespace l2 {

namespace png_codec {
class RegionReader;
}

// The image cache's limit where no one says (--picture-cache-mb): what a picture stored as
// scanlines took to be held whole before the limit could be set.
inline constexpr double kDefaultPictureCacheMegabytes = 512;

class PictureRegions {
 public:
  // Through an image cache holding at most `cache_megabytes` of decoded tiles: a picture stored
  // as scanlines (PNG, JPEG) that fits in it is decoded once; a larger one is decoded again
  // for the rows the cache let go. Throws std::runtime_error naming the file and why, in one
  // line ("pic.tif: cannot read: a TIFF file: ..."), when it is missing, damaged, empty or not
  // a picture.
  explicit PictureRegions(const std::filesystem::path& path,
                          double cache_megabytes = kDefaultPictureCacheMegabytes);
  ~PictureRegions();
  PictureRegions(const PictureRegions&) = delete;
  PictureRegions& operator=(const PictureRegions&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // MIP levels the file holds (1: none); level 0 is the picture, each level after it half the
  // sides of the one before (rounded either way, at least 1: a file whose levels do not halve
  // is refused when opened).
  int levels() const;
  int width(int level) const;
  int height(int level) const;

  // Columns [x_begin, x_end) of row y as 8-bit RGB (grey spread over R, G and B, alpha
  // dropped) into `rgb`, which holds (x_end - x_begin) * 3 bytes. The range must lie in the
  // picture. Throws std::runtime_error naming the file when the pixels cannot be read.
  void read_row(int y, int x_begin, int x_end, std::uint8_t* rgb) const {
    read_row(0, y, x_begin, x_end, rgb);
  }
  // The same at MIP level `level` (in [0, levels())), its range within that level.
  void read_row(int level, int y, int x_begin, int x_end, std::uint8_t* rgb) const;

 private:
  std::filesystem::path path_;
  std::unique_ptr<png_codec::RegionReader> reader_;
  int width_ = 0, height_ = 0;
};

}  // namespace l2
