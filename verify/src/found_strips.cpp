#include "found_strips.hpp"

#include "strip_headers/scanline_parser.hpp"

namespace l2::verify_detail {
namespace {

// Refusals named by place in the report; the rest are counted only.
constexpr std::size_t kRefusalsNamed = 8;

// The error kind the parser counted between `before` and `after` (one scanline stops at its
// first refusal).
const char* refusal_kind(const StripErrorCounts& before, const StripErrorCounts& after) {
  if (after.check_errors != before.check_errors) return "check-bit error";
  if (after.ext_unsupported != before.ext_unsupported) return "unsupported EXT strip";
  if (after.zero_width != before.zero_width) return "zero-width strip";
  return "truncated strip";
}

int parity_with(int parity, bool frame) {
  const int p = frame ? 1 : 0;
  if (parity == kNoParity) return p;
  return parity == p ? p : kMixedParity;
}

}  // namespace

std::vector<FoundStrip> find_strips(std::span<const RgbImage> frames,
                                    std::vector<InputCheck>& inputs,
                                    std::vector<FoundStrip>* skips) {
  std::vector<FoundStrip> strips;
  inputs.clear();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const RgbImage& frame = frames[i];
    InputCheck check;
    check.input = static_cast<int>(i);
    check.width = frame.width();
    check.height = frame.height();
    for (int y = 0; y < frame.height(); ++y) {
      const std::uint8_t* row = frame.row(y).data();
      const StripErrorCounts before = check.errors;
      int next_header = 0;  // where the parser reads next: a refusal happens there
      int last_header = 0;  // a strip running past the scanline is refused at its own header
      parse_scanline(
          row, frame.width(), RgbImage::kChannels, check.errors, [&](const ParsedStrip& s) {
            next_header = s.next_header_x();
            last_header = s.header_x();
            check.parity = parity_with(check.parity, s.header.frame);
            const std::uint8_t* h = row + static_cast<std::ptrdiff_t>(s.header_x()) * 3;
            if (s.header.op == StripOp::Skip) {
              if (skips) {
                skips->push_back({check.input, y, s.source_x, s.length, header_value(h, h + 3),
                                  s.header, Compositing::Copy, 0, 0});
              }
              return;
            }
            Compositing how = Compositing::Copy;
            if (s.is(ExtKind::Key)) how = Compositing::Key;
            if (s.is(ExtKind::Depth)) how = Compositing::Depth;
            ++(how == Compositing::Copy ? check.copy_strips : check.composited_strips);
            strips.push_back({check.input, y, s.source_x, s.length, header_value(h, h + 3),
                              s.header, how, s.extension.key, s.depth_x()});
          });
      if (check.errors.total() != before.total() && check.refused.size() < kRefusalsNamed)
        check.refused.push_back({y, next_header < frame.width() ? next_header : last_header,
                                 refusal_kind(before, check.errors)});
    }
    inputs.push_back(check);
  }
  return strips;
}

}  // namespace l2::verify_detail
