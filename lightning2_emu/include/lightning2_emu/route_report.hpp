// What routing one frame did, in counts only (the JSON writer is at the edge, report_json.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "strip_headers/scanline_parser.hpp"

namespace l2 {

// One display after a frame was completed (every strip of the frame written, background
// filled in).
struct DisplayFrameStats {
  int display = 0;  // display id
  int width = 0, height = 0;
  std::uint64_t strips = 0;  // COPY, KEY and DEPTH strips routed to it (after clipping, non-empty)
  // Pixels that do not show the background: some strip wrote them (a KEY's transparent pixels
  // and a DEPTH's far-plane or losing pixels write nothing).
  std::uint64_t covered_pixels = 0;
  std::uint64_t overdraw_pixels = 0;  // pixels inside two or more strips (written or not)

  std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * height; }
  double coverage() const { return pixels() ? double(covered_pixels) / double(pixels()) : 0.0; }
  friend bool operator==(const DisplayFrameStats&, const DisplayFrameStats&) = default;
};

// One input frame as parsed (spec §3), before any frame-sequencing decision.
struct InputFrameStats {
  int input = 0;
  bool present = false;             // a frame was given at all
  std::uint64_t copy_strips = 0;    // COPY headers found (routed or not)
  std::uint64_t skip_strips = 0;    // SKIP headers found
  std::uint64_t key_strips = 0;     // KEY strips found (routed or not), spec §7
  std::uint64_t depth_strips = 0;   // DEPTH strips found (routed or not)
  std::uint64_t routed_strips = 0;  // COPY/KEY/DEPTH strips with at least one pixel on a display
  std::uint8_t parities = 0;        // bit p set: some header carried frame parity p
  std::uint64_t displays_fed = 0;   // bit d set: some COPY/KEY/DEPTH strip reached display d
  StripErrorCounts errors;          // every error kind of spec §3

  bool idle() const { return copy_strips + key_strips + depth_strips + skip_strips == 0; }
  bool torn() const { return parities == 3; }
  int parity() const { return parities == 2 ? 1 : 0; }  // meaningful when neither idle nor torn
  friend bool operator==(const InputFrameStats&, const InputFrameStats&) = default;
};

struct RouteReport {
  std::vector<InputFrameStats> inputs;      // one per mesh input
  std::vector<DisplayFrameStats> displays;  // one per configured display, in id order

  StripErrorCounts errors() const {
    StripErrorCounts total;
    for (const auto& i : inputs) total += i.errors;
    return total;
  }
  friend bool operator==(const RouteReport&, const RouteReport&) = default;
};

}  // namespace l2
