// A Wavefront RLA file's header, checked once its reader is chosen (the format has no signature:
// only a name ending .rla picks it). OpenImageIO's reader refuses channel counts and bits
// outside the format's, but trusts four things a header can get wrong: a matte or auxiliary
// class of channels declaring 0 bits had it rescale every sample in a loop that never ends
// (`strip_headers dump` hung on 1335 bytes: found by fuzz_picture_file); word channels of more
// than 16 bits had it rescale each pixel as 32-bit samples, writing past the end of its row
// buffer (valgrind: an invalid write of 4 bytes); and a channel type of 3, between its dword (2)
// and float (4), reached an assertion that aborted the process (found by fuzz_picture_file); and
// the offset of a next image, where a failed seek (offset -1) had it read another header from
// wherever the file stood, unchecked (the picture scene hung: found by fuzz_picture_file).
// Pure: the bytes are the caller's.
#pragma once

#include <cstddef>
#include <string_view>

#include "base/result.hpp"

namespace l2::png_codec {

// The fixed header before an RLA file's scanline table (big-endian fields).
inline constexpr std::size_t kRlaHeaderBytes = 740;

// `header`: the file's first bytes (at least kRlaHeaderBytes where the file has them; a shorter
// one is the reader's to refuse). A class of channels (colour, matte, auxiliary) that has
// channels must declare at least 1 bit (the colour class's 0 stands for 8, as the reader takes
// it), at most 16 where its type is a word (1), and a type other than 3 (the colour class's type
// whatever its count); and the file must hold one image (no next image's offset). Failure: one
// line saying what the header declares.
Status check_rla(std::string_view header);

}  // namespace l2::png_codec
