#include "image/png_io.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "image/folders.hpp"
#include "png_codec.hpp"

namespace l2 {

namespace {

// The codec module, loaded once per process (png_codec.hpp says why it is not linked) from where
// the build put it. When it cannot be loaded every picture is an error that says why.
const png_codec::Codec& codec(const std::filesystem::path& picture) {
  static const auto loaded = []() -> std::pair<const png_codec::Codec*, std::string> {
    const char* const file = L2_PNG_CODEC_MODULE;
    void* module = ::dlopen(file, RTLD_NOW | RTLD_LOCAL);  // never closed
    if (!module) return {nullptr, std::string("cannot load the image codec: ") + ::dlerror()};
    auto entry = reinterpret_cast<png_codec::EntryPoint>(::dlsym(module, png_codec::kEntryPoint));
    if (!entry) {
      // Appended, not a chain of +: GCC 12 raises a false -Warray-bounds on that chain here.
      std::string why = file;
      why.append(" has no ").append(png_codec::kEntryPoint);
      why.append(": it was built from other sources than this program (rebuild both)");
      return {nullptr, why};
    }
    return {entry(), {}};
  }();
  if (!loaded.first) throw std::runtime_error(picture.string() + ": " + loaded.second);
  return *loaded.first;
}

void check(const std::filesystem::path& path, const std::string& error) {
  if (!error.empty()) throw std::runtime_error(path.string() + ": " + error);
}

}  // namespace

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  if (path.has_parent_path()) make_folders(path.parent_path());
  check_writable(path);  // OpenImageIO says only "Could not open file"
  check(path, codec(path).write_rgb(path.c_str(), image.width(), image.height(), image.data()));
}

RgbImage read_png(const std::filesystem::path& path) {
  RgbImage image;
  const png_codec::RgbSink sink{&image,
                                [](void* context, int width, int height) {
                                  auto& out = *static_cast<RgbImage*>(context);
                                  out = RgbImage(width, height);
                                  return out.data();
                                },
                                kMaxPictureSide};
  check(path, codec(path).read_rgb(path.c_str(), sink));
  return image;
}

}  // namespace l2
