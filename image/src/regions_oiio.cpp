// Picture regions through an OpenImageIO ImageCache of its own: rows are read a tile at a time
// and the cache evicts tiles beyond its memory limit, so showing part of a picture far larger
// than memory holds only the tiles around that part.
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "media_oiio.hpp"
#include "picture_checks.hpp"
#include "picture_readers.hpp"
#include "png_chunks.hpp"
#include "png_libpng.hpp"

namespace l2::png_codec {

namespace {

namespace OIIO = OIIO_NAMESPACE;

// An interlaced PNG is read whole whatever the cache's limit; past this size it is refused.
constexpr float kWholeScanlinePictureMegabytes = 512;
// Pictures stored as scanlines are read in tiles of this side as well.
constexpr int kAutoTile = 64;

// The cache that holds a picture of `decoded_mb` whole, with room for its bookkeeping; zero for
// a picture larger than kWholeScanlinePictureMegabytes allows.
float whole_picture_cache(double decoded_mb) {
  if (decoded_mb * 1.1 > kWholeScanlinePictureMegabytes) return 0;
  return static_cast<float>(decoded_mb * 1.1 + 8);
}

struct CacheDeleter {
  void operator()(OIIO::ImageCache* cache) const { OIIO::ImageCache::destroy(cache); }
};

// Sides of more levels than this no picture has (a side of 2^31 halves to 1 in 31 steps).
constexpr int kMaxLevels = 32;

struct LevelSides {
  int width, height;
};

// Whether `side` is half of `before`, rounded down or up, and never under 1: how every writer
// of a pyramid (maketx, a TIFF's reduced-resolution directories, OpenEXR's levels) sizes a level.
bool halves(int before, int side) {
  return side == std::max(1, before / 2) || side == std::max(1, (before + 1) / 2);
}

// The sides of the picture's MIP levels as the cache reads them, level 0 first, or why one
// level does not halve the one before it (a level of another size would be sampled at pixels
// the picture scene's rule does not name).
Result<std::vector<LevelSides>> level_sides(OIIO::ImageCache& cache, OIIO::ustring file,
                                            const OIIO::ImageSpec& spec) {
  std::vector<LevelSides> sides{{spec.width, spec.height}};
  int levels = 1;
  if (!cache.get_image_info(file, 0, 0, OIIO::ustring("miplevels"), OIIO::TypeInt, &levels))
    levels = 1;
  for (int level = 1; level < std::min(levels, kMaxLevels); ++level) {
    OIIO::ImageSpec next;
    if (!cache.get_imagespec(file, next, 0, level)) break;
    const LevelSides& before = sides.back();
    if (!halves(before.width, next.width) || !halves(before.height, next.height)) {
      return Failure{"cannot read: MIP level " + std::to_string(level) + " is " +
                     std::to_string(next.width) + "x" + std::to_string(next.height) +
                     ", not half of level " + std::to_string(level - 1) + "'s " +
                     std::to_string(before.width) + "x" + std::to_string(before.height)};
    }
    sides.push_back({next.width, next.height});
  }
  return sides;
}

class CacheRegions final : public RegionReader {
 public:
  CacheRegions(std::unique_ptr<OIIO::ImageCache, CacheDeleter> cache, OIIO::ustring file,
               const OIIO::ImageSpec& spec, std::vector<LevelSides> sides)
      : cache_(std::move(cache)),
        file_(file),
        sides_(std::move(sides)),
        channels_(spec.nchannels >= 3 ? 3 : 1) {}

  int levels() const override { return static_cast<int>(sides_.size()); }
  int width(int level) const override { return sides_[static_cast<std::size_t>(level)].width; }
  int height(int level) const override { return sides_[static_cast<std::size_t>(level)].height; }

  Status read_row(int level, int y, int x_begin, int x_end, std::uint8_t* rgb) override {
    // Grey is read into the start of the row and spread over R, G and B from the end back.
    if (!cache_->get_pixels(file_, 0, level, x_begin, x_end, y, y + 1, 0, 1, 0, channels_,
                            OIIO::TypeDesc::UINT8, rgb)) {
      const std::string why = one_line(cache_->geterror());
      return Failure{"cannot read row " + std::to_string(y) +
                     (level > 0 ? " of MIP level " + std::to_string(level) : std::string()) + ": " +
                     (why.empty() ? "damaged" : why)};
    }
    if (channels_ == 1) {
      for (int i = x_end - x_begin - 1; i >= 0; --i) {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = rgb[i];
      }
    }
    return {};
  }

 private:
  std::unique_ptr<OIIO::ImageCache, CacheDeleter> cache_;
  OIIO::ustring file_;
  std::vector<LevelSides> sides_;
  int channels_;
};

}  // namespace

// A PNG's chunks, checked before the cache trusts its header (png_chunks.hpp), then, with
// `rows`, its rows decoded (check_png_data): nothing for another format; else the megabytes it
// decodes to as stored, or why it cannot be read.
Result<double> png_megabytes(const char* path, bool rows) {
  {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
    if (!file || !is_png(file.get())) return 0.0;  // damaged in transfer too: png_layout says so
  }
  const Result<PngLayout> png = png_layout(path);
  if (!png.ok()) return Failure{png.reason()};
  const double megabytes = png->decoded_bytes() / (1 << 20);
  // The cache reads an interlaced PNG whole; one larger than it may hold aborted the process.
  if (png->interlaced && whole_picture_cache(megabytes) == 0) {
    return Failure{"cannot read: an interlaced PNG of " + std::to_string(png->width) + "x" +
                   std::to_string(png->height) + " pixels is read whole, " +
                   std::to_string(static_cast<long long>(megabytes)) +
                   " MiB, more than a picture read whole may take (" +
                   std::to_string(static_cast<int>(kWholeScanlinePictureMegabytes)) +
                   " MiB of cache); save it without interlacing"};
  }
  if (rows) {
    if (const Status data = check_png_data(path); !data.ok()) return Failure{data.reason()};
  }
  return megabytes;
}

// The cache holds at most `cache_megabytes` of decoded tiles, whatever the picture's size. A
// picture stored as scanlines (PNG, JPEG) cannot be read from its middle: a tile the cache
// evicted is decoded again from the first row; one that fits in the limit is decoded once.
namespace {

// The picture's header checked (picture_checks.hpp: what a reader would trust of it, first),
// then opened once directly, so that a file that cannot be read gets the same one-line reason
// as read_png: its sides and storage, or why not. `rows`: a PNG's rows decoded too, before a
// reader decodes them (its own lines on stderr, a damaged row a frame into the run).
// `format`: the format its reader read it as, which the image cache then reads it as.
Result<PictureShape> checked_shape(const char* path, bool rows, std::string* format = nullptr) {
  const Result<double> png = png_megabytes(path, rows);
  if (!png.ok()) return Failure{png.reason()};
  const PictureBytes bytes = file_bytes(path);
  const Result<HeaderFacts> facts = check_before_open(bytes);
  if (!facts.ok()) return Failure{facts.reason()};
  const Result<std::unique_ptr<OIIO::ImageInput>> in = open_reader(path);
  if (!in.ok()) return Failure{in.reason()};
  const OIIO::ImageSpec& spec = (*in)->spec();
  if (spec.deep || spec.depth > 1) {
    return Failure{"cannot read: a deep or volume image, not a picture"};
  }
  if (spec.width <= 0 || spec.height <= 0) {
    return Failure{"cannot read: the picture has no pixels"};
  }
  if (const Status s = check_opened(**in, bytes.size, true, facts->decoded_whole); !s.ok())
    return Failure{s.reason()};
  if (format) *format = (*in)->format_name();
  return PictureShape{spec.width, spec.height, spec.tile_width > 0,
                      double(spec.width) * spec.height * 3 / (1 << 20)};
}

}  // namespace

// Only the header: what picture_to_read asks of every picture, which open_regions or
// make_tiled_copy then checks whole.
Result<PictureShape> picture_shape(const char* path) try {
  return checked_shape(path, false);
} catch (const std::exception& e) {
  return Failure{std::string("cannot read: ") + e.what()};
}

Result<PictureShape> checked_picture(const char* path) try {
  return checked_shape(path, true);
} catch (const std::exception& e) {
  return Failure{std::string("cannot read: ") + e.what()};
}

Result<std::unique_ptr<RegionReader>> open_regions(const char* path, float cache_megabytes) try {
  std::string format;
  if (const Result<PictureShape> shape = checked_shape(path, true, &format); !shape.ok())
    return Failure{shape.reason()};
  std::unique_ptr<OIIO::ImageCache, CacheDeleter> cache(OIIO::ImageCache::create(false));
  cache->attribute("max_memory_MB", cache_megabytes);
  cache->attribute("autotile", kAutoTile);
  const OIIO::ustring file(path);
  OIIO::ImageSpec spec;
  if (!cache->add_file(file, reader_creator(format)) || !cache->get_imagespec(file, spec)) {
    return Failure{"cannot read: " + one_line(cache->geterror())};
  }
  Result<std::vector<LevelSides>> sides = level_sides(*cache, file, spec);
  if (!sides.ok()) return Failure{sides.reason()};
  return std::unique_ptr<RegionReader>(
      new CacheRegions(std::move(cache), file, spec, std::move(sides).value()));
} catch (const std::exception& e) {
  return Failure{std::string("cannot read: ") + e.what()};
}

}  // namespace l2::png_codec
