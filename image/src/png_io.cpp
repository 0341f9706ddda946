#include "image/png_io.hpp"

#include <dlfcn.h>

#include <cctype>
#include <exception>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "image/folders.hpp"
#include "png_codec.hpp"
#include "png_libpng.hpp"

namespace l2 {

// The codec module, loaded once per process (png_codec.hpp says why it is not linked). Installed
// (cmake/Install.cmake), it is in PREFIX/lib/lightning2, found by its name through the run path
// of the installed programs and of programs built against the installed package; in a build
// tree, where the build put it, which a program of the tree has no run path to. When it cannot be
// loaded every picture is an error that says why.
const png_codec::Codec& png_codec::codec(const std::filesystem::path& picture) {
  static const auto loaded = []() -> std::pair<const png_codec::Codec*, std::string> {
    const char* file = L2_PNG_CODEC_NAME;
    void* module = ::dlopen(file, RTLD_NOW | RTLD_LOCAL);  // never closed
    if (!module) {
      std::string installed = ::dlerror();
      file = L2_PNG_CODEC_MODULE;
      module = ::dlopen(file, RTLD_NOW | RTLD_LOCAL);
      if (!module) {
        std::string why = "cannot load the image codec: ";
        why.append(installed).append("; ").append(::dlerror());
        return {nullptr, why};
      }
    }
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

namespace {

void check(const std::filesystem::path& path, const Status& status) {
  if (!status.ok()) throw std::runtime_error(path.string() + ": " + status.reason());
}

// Where the codec puts a picture: an RgbImage, once `accept` has taken its size. What `accept`
// throws is kept here and thrown once the codec has returned: no exception may cross the module
// or libpng's C frames.
struct Target {
  RgbImage image;
  const SizeCheck& accept;
  std::exception_ptr refused;

  png_codec::RgbSink sink() {
    return {this,
            [](void* context, int width, int height) {
              auto& out = *static_cast<Target*>(context);
              try {
                if (out.accept) out.accept(width, height);
                return true;
              } catch (...) {
                out.refused = std::current_exception();
                return false;
              }
            },
            [](void* context, int width, int height) -> std::uint8_t* {
              auto& out = *static_cast<Target*>(context);
              try {
                out.image = RgbImage(width, height);
                return out.image.data();
              } catch (const std::bad_alloc&) {
                return nullptr;
              }
            },
            kMaxPictureSide};
  }
  // The picture read, or what `accept` threw, or the codec's failure naming `name`.
  RgbImage take(const std::filesystem::path& name, const Status& read) {
    if (refused) std::rethrow_exception(refused);
    check(name, read);
    return std::move(image);
  }
};

// Whether `path` names a PNG file by its extension, as OpenImageIO chooses a writer (any case).
bool png_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// `input` read here with libpng when it is a PNG (no module loaded); nothing when it is not (or
// cannot be opened), for the module to read, which also says why a file cannot be opened.
std::optional<Status> read_if_png(const png_codec::Input& input, Target& target,
                                  png_codec::Source& found) {
  const png_codec::Stream file = png_codec::open_stream(input);
  if (!file || !png_codec::is_png(file.get())) return std::nullopt;
  return png_codec::read_png(file.get(), target.sink(), found);
}

// `image` as PNG bytes (libpng, no module); a failure names `name`, the file or "in memory".
std::string encode_rgb(const std::filesystem::path& name, const RgbImage& image) {
  std::string bytes;
  check(name, png_codec::encode_pixels(image.width(), image.height(), 3, image.data(), &bytes));
  return bytes;
}

}  // namespace

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  if (path.has_parent_path()) make_folders(path.parent_path());
  if (png_extension(path)) {
    write_whole_file(path, encode_rgb(path, image));
    return;
  }
  Result<std::string> encoded =
      png_codec::codec(path).encode_file(path.c_str(), image.width(), image.height(), image.data());
  if (!encoded.ok()) throw std::runtime_error(path.string() + ": " + encoded.reason());
  write_whole_file(path, *encoded);
}

std::string encode_png(const RgbImage& image) {
  return encode_rgb("a PNG in memory", image);
}

std::string encode_grey_png(int width, int height, std::span<const std::uint8_t> grey) {
  if (width < 1 || height < 1 || grey.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("encode_grey_png: the bytes are not width x height");
  std::string bytes;
  check("a grey PNG in memory", png_codec::encode_pixels(width, height, 1, grey.data(), &bytes));
  return bytes;
}

RgbImage read_png(const std::filesystem::path& path, PictureSource* source,
                  const SizeCheck& accept) {
  Target target{RgbImage(), accept, nullptr};
  png_codec::Source found;
  std::optional<Status> read = read_if_png({path.c_str()}, target, found);
  if (!read) read = png_codec::codec(path).read_rgb(path.c_str(), target.sink(), &found);
  RgbImage image = target.take(path, *read);
  if (source) *source = {found.format, found.colour_channels, found.lossy};
  return image;
}

RgbImage read_picture_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                            const std::string& format_hint, const SizeCheck& accept) {
  Target target{RgbImage(), accept, nullptr};
  png_codec::Source found;
  // fmemopen refuses an empty buffer: no bytes are the module's to refuse.
  std::optional<Status> read;
  if (!bytes.empty())
    read = read_if_png({nullptr, bytes.data(), bytes.size(), format_hint.c_str()}, target, found);
  if (!read)
    read = png_codec::codec(name).read_rgb_bytes(bytes.data(), bytes.size(), format_hint.c_str(),
                                                 target.sink(), nullptr);
  return target.take(name, *read);
}

RgbImage read_scanned_frame(const std::filesystem::path& path, const SizeCheck& accept) {
  PictureSource source;
  RgbImage frame = read_png(path, &source, accept);
  if (source.colour_channels < 3) {
    throw std::runtime_error(path.string() +
                             ": a grayscale picture (one colour channel) cannot hold strip "
                             "headers: a header is 48 bits in the R, G and B bytes of two pixels");
  }
  if (source.lossy) {
    std::string kind = "a JPEG picture";
    if (source.format != "jpeg") {
      kind = "a ";
      for (const unsigned char c : source.format) kind += static_cast<char>(std::toupper(c));
      kind += " picture with JPEG compression";
    }
    throw std::runtime_error(path.string() + ": " + kind +
                             " cannot hold strip headers: the lossy compression changes pixel "
                             "bytes (save frames as PNG)");
  }
  return frame;
}

}  // namespace l2
