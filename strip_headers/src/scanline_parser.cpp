#include "strip_headers/scanline_parser.hpp"

namespace l2 {

StripErrorCounts& StripErrorCounts::operator+=(const StripErrorCounts& o) {
  check_errors += o.check_errors;
  ext_unsupported += o.ext_unsupported;
  zero_width += o.zero_width;
  truncations += o.truncations;
  missing_display += o.missing_display;
  clips += o.clips;
  return *this;
}

std::uint64_t StripErrorCounts::total() const {
  return check_errors + ext_unsupported + zero_width + truncations + missing_display + clips;
}

}  // namespace l2
