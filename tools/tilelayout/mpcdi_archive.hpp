// The MPCDI archive at the edge: a zip file (libzip) of mpcdi.xml and the files it names, read
// with a bound on every entry, so that a zip bomb (a few KiB that inflate to gigabytes) is one
// line instead of a full disk. What the files mean is l2_wall_import's (import_mpcdi).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

struct zip;

namespace l2 {

// An entry is at most this large uncompressed: a warp of a 4095x4095 display (3 floats a point)
// and its header, with room to spare; a map of that size is smaller.
inline constexpr std::uint64_t kMaxMpcdiEntryBytes = 256ull << 20;

// Whether `bytes` begin as a zip file does ("PK\3\4", or "PK\5\6" for an empty one).
bool looks_like_zip(std::string_view bytes);

class MpcdiArchive {
 public:
  // Opens the zip file held in `bytes` (kept by the archive); `file` names it in messages.
  // Throws LayoutError "FILE: not a zip archive: ..." with libzip's reason.
  MpcdiArchive(std::string bytes, std::string file);
  ~MpcdiArchive();
  MpcdiArchive(const MpcdiArchive&) = delete;
  MpcdiArchive& operator=(const MpcdiArchive&) = delete;

  // The names of its files, in archive order (folders left out).
  const std::vector<std::string>& entries() const { return entries_; }
  // An entry's bytes, at most `limit` of them: throws LayoutError "FILE: ENTRY: inflates to
  // more than N bytes ..." for a larger one (as declared, and as read: a declared size is not
  // trusted), "FILE: ENTRY: not in the archive", or libzip's reason for a damaged one.
  std::string read(const std::string& entry, std::uint64_t limit = kMaxMpcdiEntryBytes) const;

 private:
  std::string bytes_;
  std::string file_;
  zip* zip_ = nullptr;
  std::vector<std::string> entries_;
};

}  // namespace l2
