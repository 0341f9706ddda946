// `l2wall golden check`: reproduces every golden entry and compares, for each display,
//   the emulator's display with the golden image: exactly (within the entry's tolerance when a
//     rendered entry's images were made by another GL implementation, which it says);
//   the viz path's display with the emulator's: exactly;
//   the emulator's display with the reference (test pattern or reference render): within the
//     entry's tolerance.
// A mismatch writes the actual image and a diff picture to OUT/<entry>/ and prints one summary
// line per differing display.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "golden_entry.hpp"

namespace l2 {

struct CheckOptions {
  GoldenPaths paths;
  std::filesystem::path out = "golden-check";
  std::vector<std::string> entries;  // empty: every entry
  // Captured scanned-out frames (scanout-<i>.png) to route instead of producing the entry's
  // frames; needs exactly one routing-only entry.
  std::filesystem::path inputs;
  bool write_actual = false;  // write every display's actual image, passing or not
  GoldenTools tools;          // render the rendered entries
};

// Exit code: 0 every entry passed, 1 some entry failed. Throws GoldenError when the check
// cannot start (manifest, entry names, --inputs misuse).
int run_golden_check(const CheckOptions& options, std::ostream& out);

}  // namespace l2
