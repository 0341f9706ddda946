// A TIFF's directories, walked from the file before OpenImageIO opens it. Its header is spread
// over the file: each directory (a page, or a level of a pyramid) names the next by offset, and
// the image cache reads every one as it opens the file, each by walking the chain from the
// first again: a 2.3 MB TIFF of 20,000 one-pixel directories held the picture scene for minutes.
// And the first directory's size, samples and tiles are what the readers trust: a 434-byte TIFF
// of 1024x1024 pixels in one tile of 65536x65536 had a whole-picture read take 13 GB. Pure: the
// bytes come through a function.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "image/declared_size.hpp"

namespace l2::png_codec {

// More directories than a pyramid of the largest side has levels, and than any picture a wall
// shows needs pages; the picture scene shows the first.
inline constexpr int kMaxTiffDirectories = 256;

// The file's bytes [offset, offset + size), fewer where the file ends first.
using ReadAt = std::function<std::string(std::uint64_t offset, std::size_t size)>;

// What a TIFF's (classic or BigTIFF, either byte order) first directory declares, and how many
// directories its chain holds (a chain that loops ends where it loops, as libtiff ends it).
// Nothing when the bytes are no TIFF; a directory past the file's end or cut short is left to
// the reader, which says so.
struct TiffFacts {
  bool tiff = false;
  int directories = 0;  // counted up to kMaxTiffDirectories + 1
  Declared first;       // format "tiff"; sides 0 when the directory does not give them
  // Every directory's declaration, the first included: a pyramid's levels (or a file's pages),
  // each read by the image cache when the view asks for it.
  std::vector<Declared> each;
  std::vector<std::uint64_t> schemes;         // by directory, its compression scheme's number
  std::vector<std::uint64_t> rows_per_strip;  // by directory, its RowsPerStrip (0: none given)
};
TiffFacts tiff_facts(const ReadAt& read, std::uintmax_t file_size);

// tiff_facts checked: the chain's length, then every directory through check_declared (a
// level of a pyramid declaring tiles of 65536x65536, or more pixels than the file holds, is
// refused as the first would be), tiles of one side 0, and strips holding more than
// kMaxWholeMegabytes. Failure: one line saying what the file declares, and which directory after
// the first.
Status check_tiff(const ReadAt& read, std::uintmax_t file_size);

}  // namespace l2::png_codec
