// Rendered golden entries: the frame rendered by real pipeserver processes in a live run
// (`l2wall run --path both --compare`), its displays on both paths read back, and the
// reference render of every display (`pipeserver --reference`). Rendering stays out of this
// process: l2wall links libGL for its display windows, whose GL symbols would shadow OSMesa's.
#pragma once

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden_manifest.hpp"
#include "golden_routing.hpp"
#include "pipeserver/gl_context.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// `l2wall golden` stopped by SIGINT or SIGTERM (it records them: golden_command.cpp): thrown
// between entries, or once the commands of a rendered entry have ended; what `what()` says is
// "stopped by signal 15 (Terminated)".
struct GoldenStopped : std::runtime_error {
  explicit GoldenStopped(int signal);
};
// Throws GoldenStopped once a stop signal came.
void throw_if_stopped();

struct RenderedRun {
  std::string l2wall;              // the executable whose `run` subcommand renders the frame
  std::string pipeserver_program;  // renders the reference
  std::filesystem::path work;      // the run's --out folder, and the commands' logs
  std::filesystem::path session;   // scene "session": its file; otherwise empty
  std::chrono::seconds timeout{180};
};

// Runs frames 0..entry.frame of entry.scene on the wall, keeping the last, with every frame
// compared byte for byte on both paths by the run itself (DVI path only when the entry has no
// vizserver path). Throws std::runtime_error when a command fails, naming its log.
EntryDisplays produce_rendered(const TileLayout& layout, const std::filesystem::path& wall_file,
                               const GoldenEntry& entry, const RenderedRun& run);

// A live pipeserver whose framebuffer has no room for a stamp strip writes the frame number into
// the first pixel of its first tile (pipeserver/src/live_mode.cpp); the reference render has no
// such pixel, so it is added there.
void stamp_references(const TileLayout& layout, int frame, std::vector<RgbImage>& references);

// A re-tiled wall moves the frame stamps (each pipeserver's first tile's first pixel), so a
// golden image made before shows them elsewhere. Sets each pixel of `actual` that differs from
// `expected` only by being a stamp (one side holds frame `frame`'s stamp colour) to expected's,
// and returns how many; none when more differ so than `pipeservers` stamps can explain (two
// places each: where they were and where they are).
int set_aside_moved_stamps(int frame, int pipeservers, const std::vector<RgbImage>& expected,
                           std::vector<RgbImage>& actual);

// What `pipeserver --gl-info` reports: the GL implementation the pipeservers render with.
// Throws std::runtime_error when it cannot be asked.
GlInfo pipeserver_gl_info(const std::string& pipeserver, const std::filesystem::path& work);

}  // namespace l2
