// MpcdiArchive: libzip over the file's bytes in memory, every entry read with a bound.
#include "mpcdi_archive.hpp"

#include <fmt/format.h>
#include <zip.h>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

std::string zip_reason(zip_error_t* error) {
  const std::string reason = zip_error_strerror(error);
  zip_error_fini(error);
  return reason;
}

}  // namespace

bool looks_like_zip(std::string_view bytes) {
  return bytes.starts_with(std::string_view("PK\x03\x04", 4)) ||
         bytes.starts_with(std::string_view("PK\x05\x06", 4));
}

MpcdiArchive::MpcdiArchive(std::string bytes, std::string file)
    : bytes_(std::move(bytes)), file_(std::move(file)) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(bytes_.data(), bytes_.size(), 0, &error);
  if (source) zip_ = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
  if (!zip_) {
    if (source) zip_source_free(source);
    throw LayoutError(
        fmt::format("{}: not a zip archive (an MPCDI file is one): {}", file_, zip_reason(&error)));
  }
  zip_error_fini(&error);
  const zip_int64_t count = zip_get_num_entries(zip_, 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(zip_, static_cast<zip_uint64_t>(i), 0);
    if (name && *name && std::string_view(name).back() != '/') entries_.emplace_back(name);
  }
}

MpcdiArchive::~MpcdiArchive() {
  if (zip_) zip_discard(zip_);
}

std::string MpcdiArchive::read(const std::string& entry, std::uint64_t limit) const {
  const zip_int64_t index = zip_name_locate(zip_, entry.c_str(), 0);
  if (index < 0) throw LayoutError(fmt::format("{}: {}: not in the archive", file_, entry));
  const auto too_large = [&] {
    return LayoutError(fmt::format(
        "{}: {}: inflates to more than {} bytes, more than any file of a calibration: refused "
        "(a damaged or hostile archive)",
        file_, entry, limit));
  };
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(zip_, static_cast<zip_uint64_t>(index), 0, &st) == 0 &&
      (st.valid & ZIP_STAT_SIZE) && st.size > limit)
    throw too_large();
  zip_file_t* f = zip_fopen_index(zip_, static_cast<zip_uint64_t>(index), 0);
  if (!f) {
    throw LayoutError(fmt::format("{}: {}: cannot be read: {}", file_, entry, zip_strerror(zip_)));
  }
  std::string out;
  char chunk[1 << 16];
  for (;;) {
    const zip_int64_t n = zip_fread(f, chunk, sizeof chunk);
    if (n < 0) {
      const std::string reason = zip_error_strerror(zip_file_get_error(f));
      zip_fclose(f);
      throw LayoutError(fmt::format("{}: {}: cannot be read: {}", file_, entry, reason));
    }
    if (n == 0) break;
    if (out.size() + static_cast<std::uint64_t>(n) > limit) {
      zip_fclose(f);
      throw too_large();
    }
    out.append(chunk, static_cast<std::size_t>(n));
  }
  zip_fclose(f);
  return out;
}

}  // namespace l2
