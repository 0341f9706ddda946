// The edges of a verification, shared by `lightning2_emu route --verify` and
// `tilelayout --verify`: routing frames the way the wall's mesh would, and writing the
// check's pictures and report.
#pragma once

#include <filesystem>
#include <ostream>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "tilelayout/tile_layout.hpp"
#include "verify/routing_check.hpp"

namespace l2 {

// The exit status of a verification that found anything wrong.
inline constexpr int kExitRoutingWrong = 4;

// Routes one frame per input through the smallest mesh the wall fits (as lightning2_emu route
// --wall does, background black): what each display shows, in wall order. Throws MeshError for
// a frame the mesh refuses.
std::vector<RgbImage> route_on_wall(const Wall& wall, std::span<const RgbImage> frames,
                                    int workers = 0);

// Checks `frames` against the wall's plan, reading pixels from `routed` (per display, wall
// order), writes OUT/verify-<d>.png and prints the report to `out`. Returns whether the routing
// is right. Throws std::runtime_error when a picture cannot be written.
bool verify_and_report(const TileLayout& layout, std::span<const RgbImage> frames,
                       std::span<const RgbImage* const> routed, const std::filesystem::path& dir,
                       std::ostream& out);

}  // namespace l2
