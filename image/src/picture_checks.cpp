#include "picture_checks.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>

#include "byte_fields.hpp"
#include "image/fits_header.hpp"
#include "image/ico_header.hpp"
#include "media_oiio.hpp"
#include "png_libpng.hpp"

namespace l2::png_codec {

namespace {

// More images than any icon holds (each size and depth of one picture).
constexpr std::uint32_t kMaxIcoImages = 256;
// What an icon's PNG header is read from, for the images after the first.
constexpr std::size_t kIcoHeaderBytes = 1 << 20;

// A file descriptor closed with the last reader that holds it.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// An ICO's images that are PNGs, checked with libpng before OpenImageIO's ICO reader sees them:
// its libpng error handler crashed the process on a PNG icon cut short. Every image's header;
// the first's rows too (the one a picture shows), unless it is larger than any picture decoded
// whole may be, which check_opened refuses once the header is read.
Status check_ico(const PictureBytes& bytes) {
  const std::string head = bytes.read(0, 6);
  if (head.size() < 6 || le(head, 0, 2) != 0 || le(head, 2, 2) != 1) return {};
  const std::uint32_t count = le(head, 4, 2);
  if (count > kMaxIcoImages) {
    return Failure{"cannot read: an ICO declaring " + std::to_string(count) +
                   " images, more than the " + std::to_string(kMaxIcoImages) + " read here"};
  }
  const std::string entries = bytes.read(6, 16 * count);
  std::set<std::uint32_t> seen;
  for (std::uint32_t i = 0; i < count && 16 * i + 16 <= entries.size(); ++i) {
    const std::uint32_t offset = le(entries, 16 * i + 12, 4);
    // An image is a PNG to the reader when its bytes 1 to 3 say "PNG", whatever the rest of the
    // signature (a damaged one crashed it likewise). A bitmap is checked with each entry that
    // points at it (the reader takes its sides from the entry); a PNG once.
    if (bytes.read(offset + 1, 3) != "PNG") {
      const Status s =
          check_ico_bitmap(entries.substr(16 * i, 16), bytes.read(offset, 40), offset, bytes.size);
      if (!s.ok())
        return Failure{"cannot read: an ICO's image " + std::to_string(i) + ": " + s.reason()};
      continue;
    }
    if (!seen.insert(offset).second) continue;
    // As the reader reads it: from its offset on, as far as libpng asks.
    const std::string png = bytes.read(offset, i == 0 ? bytes.size : kIcoHeaderBytes);
    const double decoded = double(be(png, 16, 4)) * be(png, 20, 4) * 4;
    const bool rows = i == 0 && decoded <= kMaxWholeMegabytes * (1 << 20);
    if (const Status s = check_png_bytes(png, rows); !s.ok()) {
      return Failure{"cannot read: an ICO's image " + std::to_string(i) + ": " +
                     s.reason().substr(std::string("cannot read: ").size())};
    }
  }
  return {};
}

}  // namespace

PictureBytes file_bytes(const char* path) {
  auto fd = std::make_shared<Fd>();
  fd->fd = ::open(path, O_RDONLY | O_CLOEXEC);
  struct stat status {};
  const std::uintmax_t size =
      fd->fd >= 0 && ::fstat(fd->fd, &status) == 0 && S_ISREG(status.st_mode) ? status.st_size : 0;
  return {[fd, size](std::uint64_t offset, std::size_t n) {
            std::string bytes;
            if (fd->fd < 0 || offset >= size) return bytes;
            bytes.resize(static_cast<std::size_t>(std::min<std::uint64_t>(n, size - offset)));
            const ssize_t got =
                ::pread(fd->fd, bytes.data(), bytes.size(), static_cast<off_t>(offset));
            bytes.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
            return bytes;
          },
          size};
}

PictureBytes memory_bytes(const std::uint8_t* bytes, std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(bytes), size);
  return {[all](std::uint64_t offset, std::size_t n) {
            if (offset >= all.size()) return std::string();
            return std::string(all.substr(static_cast<std::size_t>(offset), n));
          },
          size};
}

Result<HeaderFacts> check_before_open(const PictureBytes& bytes) {
  const Result<HeaderFacts> facts = check_header(bytes.read(0, 4096), bytes.size);
  if (!facts.ok()) return facts;
  if (const Status tiff = check_tiff(bytes.read, bytes.size); !tiff.ok()) {
    return Failure{tiff.reason()};
  }
  if (const Status ico = check_ico(bytes); !ico.ok()) return Failure{ico.reason()};
  if (const Status exr = check_exr(bytes.read, bytes.size); !exr.ok()) {
    return Failure{exr.reason()};
  }
  if (const Status sgi = check_sgi_rle(bytes.read, bytes.size); !sgi.ok()) {
    return Failure{sgi.reason()};
  }
  if (const Status fits = check_fits(bytes.read, bytes.size); !fits.ok()) {
    return Failure{fits.reason()};
  }
  return facts;
}

Status check_opened(const OIIO_NAMESPACE::ImageInput& in, std::uintmax_t file_size, bool cached,
                    bool progressive) {
  const OIIO_NAMESPACE::ImageSpec& spec = in.spec();
  Declared d;
  d.format = in.format_name();
  d.compression = spec.get_string_attribute("compression");
  d.width = spec.width;
  d.height = spec.height;
  // As declared: a FITS of 3 axes naming only two has depth 0, on which the image cache aborts
  // (an assertion; found by fuzz_picture_file).
  d.depth = spec.depth;
  d.channels = spec.nchannels;
  d.bytes_per_channel = static_cast<int>(spec.format.size());
  d.tile_width = spec.tile_width;
  d.tile_height = spec.tile_height;
  d.tile_depth = spec.tile_width > 0 ? spec.tile_depth : 1;
  d.decoded_whole = cached && (progressive || decoded_whole_by(d.format));
  return check_declared(d, file_size);
}

}  // namespace l2::png_codec
