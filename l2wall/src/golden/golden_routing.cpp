#include "golden_routing.hpp"

#include <fmt/format.h>

#include <chrono>
#include <optional>

#include "image/png_io.hpp"
#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "pipeserver/viz_target.hpp"
#include "tilelayout/several_meshes.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/test_pattern.hpp"
#include "viz_link/tile_sender.hpp"
#include "vizserver/compositing_server.hpp"

namespace l2 {

std::vector<RgbImage> emulate_displays(const TileLayout& layout,
                                       const std::vector<RgbImage>& frames,
                                       StripErrorCounts& errors,
                                       const std::vector<std::string>& names) {
  // Each mesh its own emulator, fed by its own pipeservers (tilelayout/several_meshes.hpp).
  const std::vector<MeshPart> meshes = meshes_of(layout);
  std::vector<RgbImage> shown(layout.wall.displays.size());
  for (const MeshPart& part : meshes) {
    const bool one = meshes.size() == 1;
    // One routing thread: the result does not depend on it, and one keeps the check light.
    const EmulatorConfig config =
        emulator_config(one ? layout.wall : mesh_wall(layout.wall, part), 1);
    const std::size_t first = one ? 0 : static_cast<std::size_t>(part.first_pipeserver);
    const std::size_t count = one ? frames.size()
                                  : std::min(frames.size() - std::min(first, frames.size()),
                                             static_cast<std::size_t>(part.pipeserver_count));
    std::vector<InputFrame> inputs;
    for (std::size_t i = 0; i < count; ++i) {
      const RgbImage& f = frames[first + i];
      config.mesh.check_input(
          static_cast<int>(i), f.width(), f.height(),
          first + i < names.size() ? names[first + i] : fmt::format("pipeserver {}", first + i));
      inputs.push_back(InputFrame::of(f));
    }
    Emulator emulator(config);
    // Spec §6: frames taken in at one refresh are swapped onto the displays at the next.
    for (const InputFrameStats& input : emulator.tick(inputs).inputs) errors += input.errors;
    emulator.tick({});
    for (std::size_t k = 0; k < part.displays.size(); ++k) {
      shown[static_cast<std::size_t>(part.displays[k])] =
          emulator.shown(one ? part.displays[k] : static_cast<int>(k));
    }
  }
  return shown;
}

std::vector<RgbImage> compose_on_vizserver(const TileLayout& layout,
                                           const std::vector<RgbImage>& frames, int frame) {
  using std::chrono::milliseconds;
  viz::ServerOptions options;
  for (const Display& d : layout.wall.displays)
    options.display_sizes.emplace_back(d.width, d.height);
  options.pipeservers = static_cast<int>(layout.pipeservers.size());
  options.accept_timeout = milliseconds(10000);
  viz::CompositingServer server(options);
  server.start();
  const int display_count = static_cast<int>(layout.wall.displays.size());
  std::vector<viz::TileSender> senders;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    senders.push_back(
        viz::TileSender::connect("127.0.0.1", server.port(), plan.pipeserver, display_count));
  }
  // Each pipeserver sends its tiles straight out of its scanned-out frame, as a live pipeserver
  // does.
  const auto k = static_cast<std::uint32_t>(frame);
  for (const PipeserverPlan& plan : layout.pipeservers) {
    const RgbImage& fb = frames.at(plan.pipeserver);
    for (const PackedTile& t : plan.tiles) {
      senders[plan.pipeserver].send_tile(
          k, viz_target(t.tile), fb.row(t.fb_y).data() + static_cast<std::size_t>(t.fb_x) * 3,
          fb.stride());
    }
    senders[plan.pipeserver].finish_frame(k, static_cast<std::uint32_t>(plan.tiles.size()));
  }
  const viz::FramePtr composed = server.wait_frame(k, milliseconds(30000));
  // Read SWAPPED before closing, so no connection is reset with a message unread.
  for (viz::TileSender& s : senders) s.wait_swapped(k, milliseconds(10000));
  return composed->displays;
}

std::vector<RgbImage> test_pattern_displays(const TileLayout& layout) {
  std::vector<RgbImage> out;
  for (const Display& d : layout.wall.displays) out.emplace_back(d.width, d.height);
  for (const DisplayTile& t : layout.tiles) {
    RgbImage& image = out.at(t.display);
    const Rect& r = t.on_display;
    // The display's own map, not the tile's: a turned display's pixels show the canvas turned.
    const PanelMap m = layout.wall.displays.at(t.display).panel_map();
    for (int y = r.y; y < r.bottom(); ++y) {
      for (int x = r.x; x < r.right(); ++x)
        image.set(x, y, test_pattern(t.display, m.u(x, y), m.v(x, y)));
    }
  }
  return out;
}

EntryDisplays produce_test_pattern(const TileLayout& layout, int frame, bool vizserver) {
  EntryDisplays out;
  out.ids = display_ids(layout.wall);
  std::vector<RgbImage> frames;
  for (const PipeserverPlan& plan : layout.pipeservers)
    frames.push_back(test_frame(plan, frame % 2 == 1, PatternPlace::Canvas));
  out.emulator = emulate_displays(layout, frames, out.input_errors);
  if (vizserver) out.vizserver = compose_on_vizserver(layout, frames, frame);
  out.reference = test_pattern_displays(layout);
  out.reference_name = "test pattern";
  return out;
}

EntryDisplays produce_from_captured(const TileLayout& layout, const std::filesystem::path& dir) {
  EntryDisplays out;
  out.ids = display_ids(layout.wall);
  std::vector<RgbImage> frames;
  std::vector<std::string> names;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    const auto file = dir / fmt::format("scanout-{}.png", plan.pipeserver);
    if (!std::filesystem::exists(file)) {
      throw std::runtime_error(
          fmt::format("{}: missing: the wall has {} pipeservers, give "
                      "scanout-0.png .. scanout-{}.png",
                      file.string(), layout.pipeservers.size(), layout.pipeservers.size() - 1));
    }
    frames.push_back(read_scanned_frame(file));
    names.push_back(file.string());
  }
  out.emulator = emulate_displays(layout, frames, out.input_errors, names);
  return out;
}

}  // namespace l2
