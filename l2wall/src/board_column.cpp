#include "l2wall/board_column.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "lightning2_emu/swap_group.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {

namespace {

// The oldest frame among the stamps of the pipeservers whose strips a picture holds (by
// pipeserver, kStampNotHere for one that sent none); -1: none.
int oldest_stamp(const std::vector<int>& from) {
  int oldest = -1;
  for (const int f : from)
    if (f >= 0 && (oldest < 0 || f < oldest)) oldest = f;
  return oldest;
}

}  // namespace

BoardColumn::MeshView::MeshView(const Wall& w, std::span<const int> display_ids)
    : wall(w), mesh_id_of(w.displays.size(), -1) {
  const std::vector<MeshPart> parts = mesh_parts(w);
  const int m =
      display_ids.empty() ? 0 : w.displays.at(static_cast<std::size_t>(display_ids[0])).mesh;
  part = parts.at(static_cast<std::size_t>(w.mesh_count == 1 ? 0 : m));
  for (std::size_t i = 0; i < part.displays.size(); ++i) {
    mesh_id_of[static_cast<std::size_t>(part.displays[i])] = static_cast<int>(i);
  }
  for (const int id : display_ids) {
    const int own = mesh_id(id);
    if (own < 0) {
      throw std::invalid_argument(fmt::format("display {} is not on mesh {}", id, part.mesh));
    }
    ids.push_back(own);
  }
  if (w.mesh_count > 1) wall = mesh_wall(w, part);
}

int BoardColumn::MeshView::mesh_id(int wall_id) const {
  if (wall_id < 0 || static_cast<std::size_t>(wall_id) >= mesh_id_of.size()) return -1;
  return mesh_id_of[static_cast<std::size_t>(wall_id)];
}

BoardColumn::BoardColumn(const Wall& wall, std::span<const int> display_ids,
                         std::vector<int> pipeservers, WorkerPool& pool, bool predict)
    : mesh_(wall, display_ids),
      router_(wall_mesh(mesh_.wall), display_specs(mesh_.wall, mesh_.ids), pool),
      pipeservers_(std::move(pipeservers)),
      stamps_(static_cast<std::size_t>(mesh_.part.first_pipeserver + router_.mesh().input_count()),
              -1),
      sequences_(stamps_.size(), 0),
      back_frame_(static_cast<std::size_t>(router_.display_count()), -1),
      done_frame_(back_frame_),
      shown_frame_(back_frame_),
      back_from_(back_frame_.size(), std::vector<int>(stamps_.size(), kStampNotHere)),
      done_from_(back_from_),
      shown_from_(back_from_) {
  router_.predict_layouts(predict);
  // The wall's groups, in its numbering of them: a group may span meshes.
  for (const SwapGroup& g : make_swap_groups(display_specs(wall))) {
    std::vector<int>& own = group_indices_.emplace_back();
    for (const int id : g.displays) {
      if (const int index = router_.index_of_display(mesh_.mesh_id(id)); index >= 0)
        own.push_back(index);
    }
  }
}

bool BoardColumn::swap(std::span<const int> groups) {
  bool swapped = false;
  for (const int group : groups) {
    if (group < 0 || static_cast<std::size_t>(group) >= group_indices_.size())
      throw std::runtime_error(fmt::format("the DVI path swapped group {}", group));
    for (const int index : group_indices_[static_cast<std::size_t>(group)]) {
      router_.display(index).swap();
      const auto i = static_cast<std::size_t>(index);
      shown_frame_[i] = done_frame_[i];
      shown_from_[i] = done_from_[i];
      swapped = true;
    }
  }
  return swapped;
}

void BoardColumn::scan(std::span<const InputFrame> frames, const Tick& tick) {
  spots_ = tick.stamps;
  for (const int input : pipeservers_) {
    const auto p = static_cast<std::size_t>(input);
    if (p >= frames.size() || p >= tick.sequences.size() || !frames[p].present()) continue;
    // The spot is the new frame's: an input with none keeps the stamp it had.
    if (tick.sequences[p] == sequences_[p] || p >= spots_.size()) continue;
    sequences_[p] = tick.sequences[p];
    const InputFrame& f = frames[p];
    const StampSpot& next = spots_[p].next;
    if (next.fb_x >= 0 && next.fb_y >= 0 && next.fb_x < f.width && next.fb_y < f.height)
      stamps_[p] = decode_stamp(f.row(next.fb_y) + next.fb_x * f.bytes_per_pixel);
  }
  // The router's inputs are the mesh's: its pipeservers, from the first.
  const auto first = static_cast<std::size_t>(mesh_.part.first_pipeserver);
  const std::size_t count = std::min(static_cast<std::size_t>(mesh_.part.pipeserver_count),
                                     frames.size() > first ? frames.size() - first : 0);
  router_.scan(frames.subspan(std::min(first, frames.size()), count));
}

Observation BoardColumn::observe(std::int64_t refresh) const {
  Observation o;
  o.refresh = refresh;
  o.mesh = mesh_.part.mesh;
  for (const int input : pipeservers_) {
    const InputFrameStats& st = router_.scanned(router_input(input));
    o.inputs.push_back({input, st.present, st.idle(), st.torn(), st.parity(), st.displays_fed,
                        stamps_[static_cast<std::size_t>(input)]});
  }
  // The frame of pipeserver `p` on the display of its spot: a spot on another column's display
  // is not read here.
  const auto read = [&](std::size_t p, const StampSpot& s) -> int {
    const int own = mesh_.mesh_id(s.display);
    const int index = own < 0 ? -1 : router_.index_of_display(own);
    if (index < 0) return kStampNotHere;
    const std::vector<int>& from = shown_from_[static_cast<std::size_t>(index)];
    return p < from.size() ? from[p] : kStampNotHere;
  };
  for (std::size_t p = 0; p < spots_.size(); ++p) {
    const StampsShown shown{static_cast<int>(p), read(p, spots_[p].last),
                            read(p, spots_[p].before)};
    if (shown.last != kStampNotHere || shown.before != kStampNotHere) o.stamps.push_back(shown);
  }
  for (int d = 0; d < router_.display_count(); ++d) {
    const auto i = static_cast<std::size_t>(d);
    o.displays.push_back(
        {mesh_.wall_id(router_.display(d).id()), shown_frame_[i], 0, oldest_stamp(shown_from_[i])});
  }
  return o;
}

void BoardColumn::write(const Router::RouteChoice& choose) {
  // The path chooses by wall pipeserver; the router takes its mesh's part of that.
  std::span<const std::uint8_t> chosen;
  router_.write([&] {
    chosen = choose();
    const auto first = static_cast<std::size_t>(mesh_.part.first_pipeserver);
    if (first >= chosen.size()) return std::span<const std::uint8_t>();
    return chosen.subspan(first, std::min(chosen.size() - first,
                                          static_cast<std::size_t>(mesh_.part.pipeserver_count)));
  });
  // The frame a display's next picture holds: the newest stamp routed into it.
  for (const int input : pipeservers_) {
    const auto p = static_cast<std::size_t>(input);
    if (p >= chosen.size() || !chosen[p]) continue;
    const std::uint64_t fed = router_.scanned(router_input(input)).displays_fed;
    for (int d = 0; d < router_.display_count(); ++d) {
      if (fed >> router_.display(d).id() & 1) {
        int& f = back_frame_[static_cast<std::size_t>(d)];
        f = std::max(f, stamps_[p]);
        back_from_[static_cast<std::size_t>(d)][p] = stamps_[p];
      }
    }
  }
}

void BoardColumn::complete(std::span<const int> groups) {
  for (const int group : groups) {
    if (group < 0 || static_cast<std::size_t>(group) >= group_indices_.size())
      throw std::runtime_error(fmt::format("the DVI path completed group {}", group));
    const std::vector<int>& own = group_indices_[static_cast<std::size_t>(group)];
    router_.finish(own, finished_);
    for (const int index : own) {
      const auto i = static_cast<std::size_t>(index);
      done_frame_[i] = back_frame_[i];
      back_frame_[i] = -1;
      done_from_[i] = back_from_[i];
      std::fill(back_from_[i].begin(), back_from_[i].end(), kStampNotHere);
    }
  }
}

const RgbImage& BoardColumn::shown(int id) const {
  const int own = mesh_.mesh_id(id);
  const int index = own < 0 ? -1 : router_.index_of_display(own);
  if (index < 0) throw std::out_of_range(fmt::format("display {} is not this column's", id));
  return router_.display(index).front();
}

int BoardColumn::lowest_frame_shown() const {
  return shown_frame_.empty() ? -1 : *std::min_element(shown_frame_.begin(), shown_frame_.end());
}

}  // namespace l2
