#include "picture_checks.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <memory>
#include <string>

namespace l2::png_codec {

namespace {

// A file descriptor closed with the last reader that holds it.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

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
  d.depth = std::max(spec.depth, 1);
  d.channels = spec.nchannels;
  d.bytes_per_channel = static_cast<int>(spec.format.size());
  d.tile_width = spec.tile_width;
  d.tile_height = spec.tile_height;
  d.tile_depth = std::max(spec.tile_depth, 1);
  d.decoded_whole = cached && (progressive || decoded_whole_by(d.format));
  return check_declared(d, file_size);
}

}  // namespace l2::png_codec
