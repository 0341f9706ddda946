#include "image/rla_header.hpp"

#include <cstdint>
#include <string>

#include "byte_fields.hpp"

namespace l2::png_codec {

namespace {

// A class of channels as the header declares it: where its count, type and bits lie. The
// reader takes the colour class's type whatever its count, and its 0 bits for 8.
struct ChannelClass {
  const char* name;
  std::size_t count_at, type_at, bits_at;
  bool colour;
};
constexpr ChannelClass kClasses[] = {{"colour", 20, 18, 658, true},
                                     {"matte", 22, 660, 662, false},
                                     {"auxiliary", 24, 664, 666, false}};
// The format's types: 0 byte, 1 word, 2 dword, 4 float. The reader refuses those past 4 and
// below 0, but 3 reached its assertion (the process aborted).
constexpr int kWord = 1, kNoType = 3;

int field(std::string_view h, std::size_t at) {
  return static_cast<std::int16_t>(be(h, at, 2));
}

}  // namespace

Status check_rla(std::string_view h) {
  if (h.size() < kRlaHeaderBytes) return {};
  // The offset of a next image, which the image cache looks for as it opens the file: the reader
  // seeks there, and where the seek fails reads a header from wherever the file stands.
  if (const auto next = static_cast<std::int32_t>(be(h, 736, 4)); next != 0) {
    return Failure{"cannot read: an RLA file declaring a next image at byte " +
                   std::to_string(next) + "; RLA files of one image are read here"};
  }
  for (const ChannelClass& c : kClasses) {
    const int count = field(h, c.count_at), type = field(h, c.type_at);
    const int bits = field(h, c.bits_at) == 0 && c.colour ? 8 : field(h, c.bits_at);
    const std::string declares = "cannot read: an RLA file declaring " + std::to_string(count) +
                                 " " + c.name + " channel(s) of " + std::to_string(bits) + " bits";
    if ((count > 0 || c.colour) && type == kNoType) {
      return Failure{declares + " of type 3 (the format's are 0, 1, 2 and 4)"};
    }
    if (count > 0 && bits < 1) return Failure{declares};
    if (count > 0 && type == kWord && bits > 16) return Failure{declares + " in 16-bit words"};
  }
  return {};
}

}  // namespace l2::png_codec
