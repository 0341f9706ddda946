// A picture stored as scanlines (PNG, JPEG), too large to hold decoded, copied once into a
// tiled TIFF with MIP levels, which the image cache then reads a tile at a time at any level.
// OpenImageIO's make_texture would hold the whole picture decoded, and says nothing of how far
// it has got; this reads the source a band of rows at a time and feeds every level at once,
// each level a band of its own rows, each coarser level the 2x2 average of the one before
// (sides halved, rounded down, never under 1: the levels picture_view.hpp's rule samples).
// Level 0 goes straight into the copy, the others into files of their own beside it, appended
// to the copy once the source is read.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "media_oiio.hpp"
#include "picture_readers.hpp"

namespace l2::png_codec {

namespace {

namespace OIIO = OIIO_NAMESPACE;

// The copy's tiles, and the rows each level gathers before writing them.
constexpr int kTile = 64;

std::unique_ptr<OIIO::ImageOutput> create_tiff(const std::string& path, int width, int height,
                                               bool first, std::string* why) {
  auto out = OIIO::ImageOutput::create("tif");
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  spec.tile_width = spec.tile_height = kTile;
  spec.attribute("compression", "zip");
  // What makes OpenImageIO read the directories after the first as MIP levels, not pages.
  if (first) spec.attribute("textureformat", "Plain Texture");
  if (!out || !out->open(path, spec)) {
    *why = "cannot write " + path + ": " + (out ? one_line(out->geterror()) : "no TIFF writer");
    return nullptr;
  }
  return out;
}

// One level of the copy being written, a band of rows at a time, feeding the next level the
// average of each pair of its rows.
class Level {
 public:
  Level(std::unique_ptr<OIIO::ImageOutput> out, std::string path, int width, int height)
      : out_(std::move(out)),
        path_(std::move(path)),
        width_(width),
        height_(height),
        band_(static_cast<std::size_t>(width) * 3 * kTile),
        held_(static_cast<std::size_t>(width) * 3) {}

  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& path() const { return path_; }
  OIIO::ImageOutput& output() { return *out_; }
  std::unique_ptr<OIIO::ImageOutput> release() { return std::move(out_); }
  void feed(Level* next) { next_ = next; }

  // The next row of this level; false (with `why`) when it could not be written.
  bool add_row(const std::uint8_t* rgb, std::string* why) {
    const std::size_t stride = static_cast<std::size_t>(width_) * 3;
    std::copy(rgb, rgb + stride, band_.begin() + static_cast<long>(stride * (row_ % kTile)));
    const int row = row_++;
    if (row_ % kTile == 0 || row_ == height_) {
      const int y0 = row - row % kTile;
      if (!out_->write_tiles(0, width_, y0, row_, 0, 1, OIIO::TypeDesc::UINT8, band_.data())) {
        *why = "cannot write " + path_ + ": " + one_line(out_->geterror());
        return false;
      }
    }
    if (next_ == nullptr) return true;
    if (height_ == 1) return next_->add_row(halved(rgb, rgb).data(), why);
    if (row % 2 == 0) {
      std::copy(rgb, rgb + stride, held_.begin());
      return true;
    }
    // An odd height's last row has no pair: the next level's side is rounded down.
    if (row / 2 >= next_->height()) return true;
    return next_->add_row(halved(held_.data(), rgb).data(), why);
  }

 private:
  // The next level's row from two of this level's: each pixel the rounded mean of four.
  std::vector<std::uint8_t> halved(const std::uint8_t* a, const std::uint8_t* b) const {
    const int w = next_->width();
    std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * 3);
    for (int i = 0; i < w; ++i) {
      const int x0 = std::min(2 * i, width_ - 1), x1 = std::min(2 * i + 1, width_ - 1);
      for (int c = 0; c < 3; ++c) {
        const int sum = a[3 * x0 + c] + a[3 * x1 + c] + b[3 * x0 + c] + b[3 * x1 + c];
        out[static_cast<std::size_t>(3 * i + c)] = static_cast<std::uint8_t>((sum + 2) / 4);
      }
    }
    return out;
  }

  std::unique_ptr<OIIO::ImageOutput> out_;
  std::string path_;
  int width_, height_;
  std::vector<std::uint8_t> band_, held_;
  int row_ = 0;
  Level* next_ = nullptr;
};

// Every level, level 0 writing `target`, the others files beside it.
std::vector<std::unique_ptr<Level>> make_levels(const std::string& target, int width, int height,
                                                std::string* why) {
  std::vector<std::unique_ptr<Level>> levels;
  for (int w = width, h = height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
    const std::string path =
        levels.empty() ? target : target + ".level-" + std::to_string(levels.size());
    auto out = create_tiff(path, w, h, levels.empty(), why);
    if (!out) return {};
    levels.push_back(std::make_unique<Level>(std::move(out), path, w, h));
    if (levels.size() > 1) levels[levels.size() - 2]->feed(levels.back().get());
    if (w == 1 && h == 1) break;
  }
  return levels;
}

// The source's rows as 8-bit RGB into level 0, a band at a time.
Status read_source(OIIO::ImageInput& in, Level& first, Progress progress) {
  const OIIO::ImageSpec& spec = in.spec();
  const int channels = spec.nchannels >= 3 ? 3 : 1;
  std::vector<std::uint8_t> band(static_cast<std::size_t>(spec.width) * channels * kTile);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(spec.width) * 3);
  std::string why;
  for (int y0 = 0; y0 < spec.height; y0 += kTile) {
    const int y1 = std::min(spec.height, y0 + kTile);
    if (!in.read_scanlines(0, 0, spec.y + y0, spec.y + y1, 0, 0, channels, OIIO::TypeDesc::UINT8,
                           band.data())) {
      return Failure{"cannot read rows " + std::to_string(y0) + ".." + std::to_string(y1) + ": " +
                     one_line(in.geterror())};
    }
    for (int y = y0; y < y1; ++y) {
      const std::uint8_t* row =
          band.data() + static_cast<std::size_t>(y - y0) * spec.width * channels;
      for (int x = 0; x < spec.width; ++x)
        for (int c = 0; c < 3; ++c) rgb[3 * x + c] = row[x * channels + (channels == 3 ? c : 0)];
      if (!first.add_row(rgb.data(), &why)) return Failure{why};
    }
    if (progress.tell) progress.tell(progress.context, double(y1) / spec.height);
  }
  return {};
}

// Level `level`'s file appended to the copy as its next directory, a band at a time.
Status append_level(OIIO::ImageOutput& copy, const std::string& target, Level& level) {
  const Result<std::unique_ptr<OIIO::ImageInput>> opened = open_reader(level.path().c_str());
  if (!opened.ok()) return Failure{"cannot read " + level.path() + ": " + opened.reason()};
  OIIO::ImageInput* in = opened->get();
  OIIO::ImageSpec spec(level.width(), level.height(), 3, OIIO::TypeDesc::UINT8);
  spec.tile_width = spec.tile_height = kTile;
  spec.attribute("compression", "zip");
  if (!copy.open(target, spec, OIIO::ImageOutput::AppendSubimage))
    return Failure{"cannot add a MIP level: " + one_line(copy.geterror())};
  std::vector<std::uint8_t> band(static_cast<std::size_t>(level.width()) * 3 * kTile);
  for (int y0 = 0; y0 < level.height(); y0 += kTile) {
    const int y1 = std::min(level.height(), y0 + kTile);
    if (!in->read_tiles(0, 0, 0, level.width(), y0, y1, 0, 1, 0, 3, OIIO::TypeDesc::UINT8,
                        band.data()) ||
        !copy.write_tiles(0, level.width(), y0, y1, 0, 1, OIIO::TypeDesc::UINT8, band.data())) {
      return Failure{"cannot copy a MIP level: " + one_line(in->geterror() + copy.geterror())};
    }
  }
  return {};
}

Status copy_levels(const char* source, const char* target, Progress progress) {
  const Result<std::unique_ptr<OIIO::ImageInput>> opened = open_reader(source);
  if (!opened.ok()) return Failure{opened.reason()};
  OIIO::ImageInput* in = opened->get();
  std::string why;
  std::vector<std::unique_ptr<Level>> levels =
      make_levels(target, in->spec().width, in->spec().height, &why);
  if (levels.empty()) return Failure{why};
  const Status read = read_source(*in, *levels.front(), progress);
  for (std::size_t l = 1; l < levels.size(); ++l) levels[l]->output().close();
  Status done = read;
  for (std::size_t l = 1; l < levels.size() && done.ok(); ++l)
    done = append_level(levels.front()->output(), target, *levels[l]);
  for (std::size_t l = 1; l < levels.size(); ++l) std::remove(levels[l]->path().c_str());
  if (!levels.front()->output().close() && done.ok())
    done = Failure{"cannot write " + std::string(target) + ": " +
                   one_line(levels.front()->output().geterror())};
  return done;
}

}  // namespace

Status make_tiled_copy(const char* source, const char* target, Progress progress) try {
  if (const Result<PictureShape> shape = checked_picture(source); !shape.ok())
    return Failure{shape.reason()};
  const Status made = copy_levels(source, target, progress);
  if (!made.ok()) std::remove(target);
  return made;
} catch (const std::exception& e) {
  std::remove(target);
  return Failure{std::string("cannot copy: ") + e.what()};
}

}  // namespace l2::png_codec
