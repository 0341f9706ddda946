#include "found_strips.hpp"

#include "strip_headers/scanline_parser.hpp"

namespace l2::verify_detail {

std::vector<FoundStrip> find_strips(std::span<const RgbImage> frames,
                                    std::vector<InputCheck>& inputs) {
  std::vector<FoundStrip> strips;
  inputs.clear();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const RgbImage& frame = frames[i];
    InputCheck check;
    check.input = static_cast<int>(i);
    for (int y = 0; y < frame.height(); ++y) {
      const std::uint8_t* row = frame.row(y).data();
      parse_scanline(
          row, frame.width(), RgbImage::kChannels, check.errors, [&](const ParsedStrip& s) {
            if (s.header.op == StripOp::Skip) return;
            Compositing how = Compositing::Copy;
            if (s.is(ExtKind::Key)) how = Compositing::Key;
            if (s.is(ExtKind::Depth)) how = Compositing::Depth;
            ++(how == Compositing::Copy ? check.copy_strips : check.composited_strips);
            const std::uint8_t* h = row + static_cast<std::ptrdiff_t>(s.header_x()) * 3;
            strips.push_back({check.input, y, s.source_x, s.length, header_value(h, h + 3),
                              s.header, how, s.extension.key, s.depth_x()});
          });
    }
    inputs.push_back(check);
  }
  return strips;
}

}  // namespace l2::verify_detail
