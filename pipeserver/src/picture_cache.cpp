// The image cache's default limit (picture_cache.hpp): the rule, and the machine's memory it
// is sized from.
#include "pipeserver/picture_cache.hpp"

#include <unistd.h>

#include <algorithm>

#include "image/picture_regions.hpp"

namespace l2 {

double default_picture_cache_mb(double physical_mb, int pipeservers) {
  // A sixteenth: the pipeservers' caches together leave the machine most of its memory for
  // their framebuffers, the emulator and the displays, and the system's own file cache.
  const double share = physical_mb / 16.0 / std::max(1, pipeservers);
  return std::max(kDefaultPictureCacheMegabytes, share);
}

double physical_memory_mb() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page) / (1 << 20);
}

}  // namespace l2
