#include "strip_headers/extension_word.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace l2 {

Extension Extension::key_colour(std::uint32_t rgb) {
  if (rgb > extension_bits::kKeyMask) {
    throw std::out_of_range(
        fmt::format("extension word key {:x} is not a colour (0..ffffff)", rgb));
  }
  return {ExtKind::Key, rgb};
}

std::uint64_t encode(const Extension& e) {
  using namespace extension_bits;
  if (e.kind == ExtKind::Depth && e.key != 0) {
    throw std::invalid_argument(
        fmt::format("extension word: DEPTH carries no key (key {:06x} given)", e.key));
  }
  const std::uint64_t key = Extension::key_colour(e.key).key;
  return with_extension_check(std::uint64_t{static_cast<std::uint8_t>(e.kind)} << kKindShift |
                              key << kKeyShift);
}

std::string to_string(const Extension& e) {
  if (e.kind == ExtKind::Depth) return "DEPTH";
  return fmt::format("KEY key={:06x}", e.key);
}

}  // namespace l2
