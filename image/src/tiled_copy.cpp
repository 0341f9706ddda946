// Which file a picture is read from (tiled_copy.hpp): the picture, or its tiled copy, found in
// the folder of copies or made there through the codec module, whole or not at all.
#include "image/tiled_copy.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

#include "png_codec.hpp"

namespace l2 {

namespace fs = std::filesystem;

namespace {

// Stable across builds and machines, unlike std::hash: a copy made by one build is found by
// the next (FNV-1a, 64 bits).
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

double threshold_from_environment(double threshold_mb) {
  const char* text = std::getenv(kTiledCopyThresholdVariable);
  if (text == nullptr || *text == '\0') return threshold_mb;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  return end != text && *end == '\0' && value >= 0 ? value : threshold_mb;
}

// The progress line: redrawn in place on a terminal, a line a tenth elsewhere (a log).
struct ProgressLine {
  std::string what;
  bool terminal = isatty(2) != 0;
  int shown = -1;

  static void tell(void* context, double done) {
    auto& line = *static_cast<ProgressLine*>(context);
    const int percent = static_cast<int>(done * 100);
    const int step = line.terminal ? percent : percent / 10 * 10;
    if (step == line.shown) return;
    line.shown = step;
    std::fprintf(stderr, line.terminal ? "\r%s: %d%%" : "%s: %d%%\n", line.what.c_str(), step);
    if (line.terminal && percent == 100) std::fputc('\n', stderr);
    std::fflush(stderr);
  }
};

fs::path make_copy(const fs::path& picture, const fs::path& copy,
                   const png_codec::PictureShape& shape) {
  std::error_code error;
  fs::create_directories(copy.parent_path(), error);
  if (error) {
    throw std::runtime_error(picture.string() + ": cannot make the folder of tiled copies " +
                             copy.parent_path().string() + ": " + error.message());
  }
  // Written under a name of this process's own, then renamed: pipeservers that copy the same
  // picture at once each finish a whole file, and none reads one cut short.
  const fs::path part = copy.string() + ".part-" + std::to_string(getpid());
  ProgressLine line{"converting " + picture.filename().string() + " (" +
                    std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                    ") into a tiled picture with mip levels"};
  const Status made = png_codec::codec(picture).make_tiled_copy(picture.c_str(), part.c_str(),
                                                                {&line, &ProgressLine::tell});
  if (!made.ok()) throw std::runtime_error(picture.string() + ": " + made.reason());
  fs::rename(part, copy, error);
  if (error) {
    fs::remove(part, error);
    throw std::runtime_error(picture.string() + ": cannot keep the tiled copy " + copy.string() +
                             ": " + error.message());
  }
  std::fprintf(stderr, "%s: tiled copy %s\n", picture.string().c_str(), copy.c_str());
  return copy;
}

}  // namespace

fs::path tiled_copy_folder() {
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache != nullptr && *cache == '/')
    return fs::path(cache) / "lightning2" / "pictures";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/')
    return fs::path(home) / ".cache" / "lightning2" / "pictures";
  return fs::temp_directory_path() / "lightning2-pictures";
}

std::string tiled_copy_name(const std::string& absolute_path, std::uintmax_t size,
                            std::int64_t mtime_ns) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(fnv1a(absolute_path + '\n' + std::to_string(size) +
                                                      '\n' + std::to_string(mtime_ns))));
  return fs::path(absolute_path).stem().string() + "-" + hash + ".tif";
}

fs::path picture_to_read(const fs::path& picture, double threshold_mb) {
  const Result<png_codec::PictureShape> shape =
      png_codec::codec(picture).picture_shape(picture.c_str());
  if (!shape.ok()) throw std::runtime_error(picture.string() + ": " + shape.reason());
  if (shape->tiled || shape->decoded_mb <= threshold_from_environment(threshold_mb)) return picture;
  std::error_code error;
  const fs::path absolute = fs::absolute(picture, error);
  const auto size = fs::file_size(picture, error);
  const auto mtime = fs::last_write_time(picture, error).time_since_epoch();
  const fs::path copy =
      tiled_copy_folder() /
      tiled_copy_name(absolute.string(), size,
                      std::chrono::duration_cast<std::chrono::nanoseconds>(mtime).count());
  if (fs::exists(copy, error)) {
    std::fprintf(stderr, "%s: using the tiled copy %s made earlier\n", picture.string().c_str(),
                 copy.c_str());
    return copy;
  }
  return make_copy(picture, copy, *shape);
}

}  // namespace l2
