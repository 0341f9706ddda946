#include "vizserver/frame_assembler.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "compose.hpp"
#include "vizserver/picture_pool.hpp"

namespace l2::viz {

FrameAssembler::FrameAssembler(std::vector<std::pair<int, int>> display_sizes, int pipeserver_count,
                               Rgb background, std::size_t max_buffered_bytes)
    : sizes_(std::move(display_sizes)),
      background_(background),
      max_buffered_bytes_(max_buffered_bytes) {
  if (pipeserver_count < 1)
    throw std::invalid_argument("FrameAssembler: need at least 1 pipeserver");
  for (const auto& [w, h] : sizes_) {
    if (w < 1 || h < 1) throw std::invalid_argument(fmt::format("display size {}x{}", w, h));
  }
  pipeservers_.resize(static_cast<std::size_t>(pipeserver_count));
  // Frames wait in the server's recent frames and the program's queue to the display stream:
  // the pool keeps up to eight frames' pictures, never more than were in use at once.
  pictures_ = PicturePool::make(8 * sizes_.size());
}

std::string FrameAssembler::name(int pipeserver) const {
  return fmt::format("pipeserver {}", pipeserver);
}

bool FrameAssembler::waits_for(const Pipeserver& s, std::uint32_t frame) const {
  return !s.lost && (!s.last_done || *s.last_done < frame);
}

Status FrameAssembler::connect(int pipeserver) {
  if (pipeserver < 0 || pipeserver >= pipeserver_count()) {
    return Failure{
        fmt::format("pipeserver id {} is outside 0..{}", pipeserver, pipeserver_count() - 1)};
  }
  if (pipeservers_[pipeserver].connected)
    return Failure{fmt::format("{} is already connected", name(pipeserver))};
  if (pipeservers_[pipeserver].lost)
    return Failure{fmt::format("{} was lost: the run goes on without it", name(pipeserver))};
  pipeservers_[pipeserver].connected = true;
  return {};
}

// A frame another pipeserver starts cannot complete if a pipeserver it waits for has left.
Status FrameAssembler::check_new_frame(std::uint32_t frame) const {
  for (int i = 0; i < pipeserver_count(); ++i) {
    const Pipeserver& s = pipeservers_[i];
    if (!s.closed || !waits_for(s, frame) || survive_losses_) continue;
    return Failure{s.last_done
                       ? fmt::format("frame {} can never complete: {} disconnected after frame {}",
                                     frame, name(i), *s.last_done)
                       : fmt::format("frame {} can never complete: {} disconnected before "
                                     "finishing any frame",
                                     frame, name(i))};
  }
  return {};
}

Status FrameAssembler::check_order(int pipeserver, std::uint32_t frame, const char* what) const {
  const Pipeserver& s = pipeservers_[pipeserver];
  if (s.last_done && frame <= *s.last_done) {
    return Failure{
        fmt::format("{}: {} for frame {} after its FRAME_DONE for frame {} (frame numbers "
                    "must increase)",
                    name(pipeserver), what, frame, *s.last_done)};
  }
  if (s.open_frame && frame != *s.open_frame) {
    return Failure{fmt::format("{}: {} for frame {} while frame {} has no FRAME_DONE",
                               name(pipeserver), what, frame, *s.open_frame)};
  }
  return {};
}

FrameAssembler::Frame& FrameAssembler::frame_entry(std::uint32_t frame) {
  Frame& f = frames_[frame];
  if (f.tiles.empty()) f.tiles.resize(pipeservers_.size());
  return f;
}

Status FrameAssembler::add_tile(int pipeserver, ReceivedTile tile) {
  const std::uint32_t number = tile.header.frame;
  if (Status e = check_order(pipeserver, number, "TILE"); !e.ok()) return e;
  if (!frames_.contains(number)) {
    if (Status e = check_new_frame(number); !e.ok()) return e;
  }
  if (buffered_bytes_ + tile.pixels.size() > max_buffered_bytes_) {
    return Failure{
        fmt::format("{}: more than {} MiB of tiles buffered waiting for frame {} (is a "
                    "pipeserver behind?)",
                    name(pipeserver), max_buffered_bytes_ >> 20, frames_.begin()->first)};
  }
  buffered_bytes_ += tile.pixels.size();
  frame_entry(number).tiles[pipeserver].push_back(std::move(tile));
  pipeservers_[pipeserver].open_frame = number;
  return {};
}

Status FrameAssembler::finish(int pipeserver, const FrameDone& done) {
  if (done.pipeserver_id != static_cast<std::uint32_t>(pipeserver)) {
    return Failure{
        fmt::format("{}: FRAME_DONE names pipeserver {}", name(pipeserver), done.pipeserver_id)};
  }
  if (Status e = check_order(pipeserver, done.frame, "FRAME_DONE"); !e.ok()) return e;
  if (!frames_.contains(done.frame)) {
    if (Status e = check_new_frame(done.frame); !e.ok()) return e;
  }
  const std::size_t arrived = frame_entry(done.frame).tiles[pipeserver].size();
  if (arrived != done.tile_count) {
    return Failure{fmt::format("{}: FRAME_DONE for frame {} announces {} tiles, {} arrived",
                               name(pipeserver), done.frame, done.tile_count, arrived)};
  }
  pipeservers_[pipeserver].last_done = done.frame;
  pipeservers_[pipeserver].open_frame.reset();
  return {};
}

Status FrameAssembler::disconnect(int pipeserver) {
  Pipeserver& s = pipeservers_[pipeserver];
  s.closed = true;
  if (survive_losses_) return {};  // lost, or the run ends: the watcher decides
  if (s.open_frame) {
    return Failure{fmt::format("{} disconnected during frame {} ({} tiles received, no FRAME_DONE)",
                               name(pipeserver), *s.open_frame,
                               frames_[*s.open_frame].tiles[pipeserver].size())};
  }
  if (auto f = frame_waiting_for(pipeserver)) {
    return Failure{s.last_done
                       ? fmt::format("{} disconnected after frame {}; frame {} is waiting for it",
                                     name(pipeserver), *s.last_done, *f)
                       : fmt::format("{} disconnected before finishing any frame; frame {} is "
                                     "waiting for it",
                                     name(pipeserver), *f)};
  }
  return {};
}

Status FrameAssembler::lose(int pipeserver) {
  if (pipeserver < 0 || pipeserver >= pipeserver_count()) {
    return Failure{
        fmt::format("pipeserver id {} is outside 0..{}", pipeserver, pipeserver_count() - 1)};
  }
  Pipeserver& s = pipeservers_[pipeserver];
  s.lost = true;
  s.open_frame.reset();
  return {};
}

std::optional<std::uint32_t> FrameAssembler::frame_waiting_for(int pipeserver) const {
  for (const auto& entry : frames_) {
    if (waits_for(pipeservers_[pipeserver], entry.first)) return entry.first;
  }
  return std::nullopt;
}

bool FrameAssembler::all_done() const {
  for (const Pipeserver& s : pipeservers_) {
    if (!s.lost && (!s.connected || !s.closed)) return false;
  }
  return frames_.empty();
}

std::vector<ComposedFrame> FrameAssembler::take_complete() {
  std::vector<ComposedFrame> out;
  while (!frames_.empty()) {
    auto it = frames_.begin();
    for (const Pipeserver& s : pipeservers_) {
      if (waits_for(s, it->first)) return out;
    }
    out.push_back(compose(it->first, it->second));
    for (const auto& pipeserver_tiles : it->second.tiles) {
      for (const ReceivedTile& t : pipeserver_tiles) buffered_bytes_ -= t.pixels.size();
    }
    keep_buffers(it->second);
    last_composed_ = it->first;
    frames_.erase(it);
  }
  return out;
}

// A composed frame's tile buffers join the spares. Pipeservers run a frame ahead, so the next
// frame's tiles may have arrived already and not taken theirs: two frames' tiles are kept,
// the oldest dropped beyond that.
void FrameAssembler::keep_buffers(Frame& frame) {
  std::size_t tiles = 0;
  for (auto& pipeserver_tiles : frame.tiles) {
    for (ReceivedTile& t : pipeserver_tiles) spare_buffers_.push_back(std::move(t.pixels));
    tiles += pipeserver_tiles.size();
  }
  if (spare_buffers_.size() > 2 * tiles) {
    spare_buffers_.erase(spare_buffers_.begin(),
                         spare_buffers_.end() - static_cast<std::ptrdiff_t>(2 * tiles));
  }
}

std::vector<std::uint8_t> FrameAssembler::take_buffer(std::size_t bytes) {
  std::vector<std::uint8_t> out;
  // The same size first (resize() then writes nothing), else any large enough.
  auto it = std::find_if(spare_buffers_.begin(), spare_buffers_.end(),
                         [&](const auto& b) { return b.size() == bytes; });
  if (it == spare_buffers_.end()) {
    it = std::find_if(spare_buffers_.begin(), spare_buffers_.end(),
                      [&](const auto& b) { return b.capacity() >= bytes; });
  }
  if (it != spare_buffers_.end()) {
    out = std::move(*it);
    *it = std::move(spare_buffers_.back());
    spare_buffers_.pop_back();
  }
  out.resize(bytes);
  return out;
}

ComposedFrame FrameAssembler::compose(std::uint32_t number, Frame& frame) {
  ComposedFrame out;
  out.frame = number;
  out.displays.reserve(sizes_.size());
  for (const auto& [w, h] : sizes_) out.displays.push_back(pictures_->take(w, h));
  // The background only where no COPY tile will write: every other pixel is written once.
  for (std::size_t d = 0; d < sizes_.size(); ++d) {
    const auto [w, h] = sizes_[d];
    copy_areas_.clear();
    for (const auto& pipeserver_tiles : frame.tiles) {
      for (const ReceivedTile& t : pipeserver_tiles) {
        if (t.header.display != d) continue;
        if (const auto area = copy_area(t.header, w, h)) copy_areas_.push_back(*area);
      }
    }
    fill_uncovered(out.displays[d], copy_areas_, background_, coverage_);
  }
  // A depth plane for every display a DEPTH tile goes to, made before any tile is applied:
  // COPY and KEY pixels written earlier on the bus must hold depth 0 there too (spec §7).
  std::vector<DepthPlane> depths(sizes_.size());
  for (const auto& pipeserver_tiles : frame.tiles) {
    for (const ReceivedTile& t : pipeserver_tiles) {
      if (t.header.how != TileKind::Depth || t.header.display >= sizes_.size()) continue;
      const auto [w, h] = sizes_[t.header.display];
      depths[t.header.display].assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h),
                                      0xFFFFFF);
    }
  }
  // Lower pipeservers first, each in arrival order: later writes win, as on the pixel bus.
  for (auto& pipeserver_tiles : frame.tiles) {
    for (ReceivedTile& t : pipeserver_tiles) {
      compose_tile(out.displays, depths, t.header, t.pixels.data(), t.header.row_bytes(),
                   out.counts);
      ++out.tiles;
    }
  }
  return out;
}

}  // namespace l2::viz
