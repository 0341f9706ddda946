// Text drawn with a TrueType font through OpenImageIO's text rendering (FreeType): the labels
// and legends of pictures and the overlay line. The font is DejaVu Sans Mono (Debian's
// fonts-dejavu-core), found by name in the system's font folders at run time.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace l2 {

// How much of each pixel of a width x height box the text covers (0..255, row by row). Row
// `above` is the top of the capitals, `cap_height` rows above the baseline: the rows above it
// hold what rises over the capitals (the dot of an i, accents), those below the baseline the
// descenders.
struct TextMask {
  int width = 0, height = 0, above = 0;
  std::vector<std::uint8_t> coverage;
};

// `text` with capitals `cap_height` pixels tall. Throws std::runtime_error in one line when the
// font cannot be found or drawn ("text: cannot draw text: ... (fonts-dejavu-core)").
TextMask render_text(std::string_view text, int cap_height);

}  // namespace l2
