// The compositing server's bookkeeping, without sockets: which pipeserver sent which tiles for
// which frame, when a frame is complete, and composing it in the order the overlap rule needs.
//
// Overlap rule (spec §5, as the emulator applies it): where tiles overlap, the tile from the
// higher pipeserver number wins; within one pipeserver the later tile wins. Tiles from
// different connections arrive interleaved in any order, so nothing is drawn on arrival: a
// frame's tiles are kept per pipeserver, in arrival order (one TCP stream keeps one
// pipeserver's order), and the frame is composed only once every pipeserver has finished it,
// pipeserver 0 first. The picture therefore never depends on network timing.
//
// Frame rules: each pipeserver's frame numbers strictly increase, and it sends all tiles of a
// frame before that frame's FRAME_DONE. A frame is complete when every pipeserver has sent a
// FRAME_DONE for it or for a later frame (a pipeserver that skips a frame number had nothing
// for it). Complete frames are composed lowest first.
//
// Losses (survive_losses, l2wall run --survive-host-loss): a pipeserver whose connection closes
// early is then not an error but awaits a verdict, and one declared lost (lose()) is waited for
// by no frame from then on: a frame is complete when every other pipeserver has finished it.
// What a lost pipeserver sent of its unfinished frame is composed with that frame.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/result.hpp"
#include "image/band_coverage.hpp"
#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz {

class PicturePool;

struct ReceivedTile {
  TileHeader header;
  std::vector<std::uint8_t> pixels;  // w*h*3 bytes, rows top to bottom
};

struct ComposedFrame {
  std::uint32_t frame = 0;
  std::vector<RgbImage> displays;  // one per display, in display order
  std::size_t tiles = 0;
  StripErrorCounts counts;  // clips and missing_display of this frame, per tile row (§3)
};

class FrameAssembler {
 public:
  FrameAssembler(std::vector<std::pair<int, int>> display_sizes, int pipeserver_count,
                 Rgb background = {}, std::size_t max_buffered_bytes = std::size_t{1} << 30);

  int pipeserver_count() const { return static_cast<int>(pipeservers_.size()); }
  int display_count() const { return static_cast<int>(sizes_.size()); }
  // The most bytes one pipeserver's TILE_DELTA tiles may hold (tile_delta.hpp): its tiles cover
  // no more than every display, a DEPTH row is two, and a frame of moving tiles may hold both
  // its old and new tiles: four times the displays' pixels.
  std::size_t tile_delta_budget() const {
    std::size_t bytes = 0;
    for (const auto& [w, h] : sizes_) bytes += std::size_t(w) * std::size_t(h) * 3;
    return 4 * bytes;
  }

  // Protocol events of pipeserver `pipeserver` (0..pipeserver_count-1). An error return is one
  // line, "pipeserver 1: ..."; the pipeserver broke the rules or the run cannot go on.
  Status connect(int pipeserver);
  Status add_tile(int pipeserver, ReceivedTile tile);
  Status finish(int pipeserver, const FrameDone& done);
  // The connection of `pipeserver` closed. Error if a frame is, or will be, waiting for it
  // (unless losses are survived: then it waits for lose() or the end of the run).
  Status disconnect(int pipeserver);
  // Frames close-ended by a pipeserver's connection do not end the run; lose() is expected.
  void survive_losses() { survive_losses_ = true; }
  // `pipeserver` is gone for good (connected or not): no frame waits for it from now on.
  // Error for an id out of range.
  Status lose(int pipeserver);
  bool lost(int pipeserver) const { return pipeservers_[pipeserver].lost; }
  bool connected(int pipeserver) const { return pipeservers_[pipeserver].connected; }

  // Removes and composes every complete frame, lowest first.
  std::vector<ComposedFrame> take_complete();

  // A buffer of `bytes` to receive a tile into: one a composed frame's tile left, when there is
  // one (tiles repeat their sizes frame to frame, so it is mostly the same size: no allocation
  // and no zero fill); else a new one.
  std::vector<std::uint8_t> take_buffer(std::size_t bytes);
  // Where composed frames' pictures come from: frames shared through its share() give their
  // pictures back for the frames after them (picture_pool.hpp).
  PicturePool& pictures() { return *pictures_; }

  // The lowest frame that exists and still waits for `pipeserver`, if any.
  std::optional<std::uint32_t> frame_waiting_for(int pipeserver) const;
  // Every pipeserver connected and disconnected, and no frame is waiting.
  bool all_done() const;
  std::optional<std::uint32_t> last_composed() const { return last_composed_; }
  std::size_t buffered_bytes() const { return buffered_bytes_; }

 private:
  struct Pipeserver {
    bool connected = false, closed = false;
    bool lost = false;                        // lose(): no frame waits for it
    std::optional<std::uint32_t> last_done;   // its last FRAME_DONE
    std::optional<std::uint32_t> open_frame;  // tiles sent, FRAME_DONE not yet
  };
  struct Frame {
    std::vector<std::vector<ReceivedTile>> tiles;  // [pipeserver] in arrival order
  };

  std::string name(int pipeserver) const;
  Status check_new_frame(std::uint32_t frame) const;
  Status check_order(int pipeserver, std::uint32_t frame, const char* what) const;
  Frame& frame_entry(std::uint32_t frame);
  bool waits_for(const Pipeserver& s, std::uint32_t frame) const;
  ComposedFrame compose(std::uint32_t number, Frame& frame);
  void keep_buffers(Frame& frame);

  std::vector<std::pair<int, int>> sizes_;
  Rgb background_;
  std::size_t max_buffered_bytes_;
  std::vector<Pipeserver> pipeservers_;
  std::map<std::uint32_t, Frame> frames_;
  std::size_t buffered_bytes_ = 0;
  std::optional<std::uint32_t> last_composed_;
  bool survive_losses_ = false;
  std::shared_ptr<PicturePool> pictures_;
  std::vector<std::vector<std::uint8_t>> spare_buffers_;  // composed tiles' pixels, for reuse
  std::vector<coverage::Area> copy_areas_;                // compose()'s scratch
  coverage::CoverageScratch coverage_;
};

}  // namespace l2::viz
