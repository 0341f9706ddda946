#include "l2wall/dvi_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <thread>
#include <utility>

#include "l2wall/live_balance.hpp"
#include "l2wall/run_fault.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {
namespace {

// For each pipeserver whose frame is new in refresh `refresh`, its frame stamp becomes
// LivePipeserver::accepted and that frame's record gets the refresh and the route time (once per
// frame). Throws RunFault for a stamp outside 0..frames-1.
void record_new_frames(PipeserverSet& pipeservers, std::vector<FrameRecord>& records,
                       std::span<const FrameKind> kinds, std::span<const int> stamps,
                       std::uint64_t refresh, RunClock::time_point t0, double route_ms) {
  const int frames = static_cast<int>(records.size());
  std::vector<int> credited;  // frames this refresh's time is already counted in
  for (std::size_t i = 0; i < pipeservers.all().size(); ++i) {
    if (kinds.size() <= i || kinds[i] != FrameKind::New) continue;
    LivePipeserver& h = pipeservers.all()[i];
    h.accepted = i < stamps.size() ? stamps[i] : -1;
    if (h.accepted < 0 || h.accepted >= frames)
      throw RunFault(
          fmt::format("pipeserver {}: frame stamp {} out of range", h.pipeserver, h.accepted));
    FrameRecord& r = records[static_cast<std::size_t>(h.accepted)];
    if (std::find(credited.begin(), credited.end(), h.accepted) == credited.end()) {
      credited.push_back(h.accepted);
      r.route_ms += route_ms;  // once per frame, however many of its pipeservers came in now
    }
    r.in_refresh = refresh;  // the last input taken in decides
    r.in_time = t0;
  }
}

// READY for the frame accepted from each pipeserver of `ready_inputs`. Fault injection:
// pipeserver 0's READY of frame `drop_ready` is held back until it asks with SYNC?. Returns how
// many READYs were held back.
int send_readies(std::span<const int> ready_inputs, PipeserverSet& pipeservers, int drop_ready) {
  int held = 0;
  for (int i : ready_inputs) {
    LivePipeserver& h = pipeservers.all()[static_cast<std::size_t>(i)];
    if (i == 0 && h.accepted == drop_ready) {
      h.held_ready = h.accepted;  // lost on the line: the pipeserver must ask with SYNC?
      ++held;
      continue;
    }
    h.channel->send_ready(static_cast<std::uint64_t>(h.accepted));
  }
  return held;
}

}  // namespace

std::optional<int> shown_by_stamps(int last, int seen_last, int seen_before) {
  if (last >= 0 && seen_last == last) return last;
  if (last >= 1 && seen_before == last - 1) return last - 1;
  if (seen_last != kStampNotHere) return seen_last;
  if (seen_before != kStampNotHere) return seen_before;
  return std::nullopt;
}

DviPath::DviPath(const TileLayout& layout, const RunOptions& o,
                 std::unique_ptr<BoardColumns> columns)
    : columns_(std::move(columns)),
      colour_(layout.wall),
      clock_(o.refresh_hz),
      refresh_hz_(o.refresh_hz),
      frames_(o.frames),
      drop_ready_(o.drop_ready),
      groups_(make_swap_groups(display_specs(layout.wall))),
      sequencer_(layout.meshes.size() > 1 ? layout.wall.pipeserver_count
                                          : wall_mesh(layout.wall).input_count(),
                 static_cast<int>(groups_.size())),
      lock_check_(groups_, eye_pairs(layout.wall)),
      eye_pairs_(static_cast<int>(eye_pairs(layout.wall).size())) {
  if (layout.wall.frame_lock.modelled) frame_lock_.emplace(layout.wall, groups_);
  if (layout.wall.stereo.mode == StereoMode::Active) {
    quad_.emplace(layout.wall.displays);
    active_check_.emplace();
  }
  if (packed_stereo(layout.wall.stereo)) packed_.emplace(layout.wall);
  // A column's displays_fed are bits of its mesh's display ids.
  const std::vector<MeshPart> meshes = meshes_of(layout);
  group_of_display_.resize(meshes.size());
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    for (const int id : groups_[g].displays) {
      const Display& d = layout.wall.displays.at(static_cast<std::size_t>(id));
      const std::vector<int>& own = meshes.at(static_cast<std::size_t>(d.mesh)).displays;
      const auto mesh_id = std::find(own.begin(), own.end(), id) - own.begin();
      group_of_display_[static_cast<std::size_t>(d.mesh)][static_cast<int>(mesh_id)] =
          static_cast<int>(g);
    }
  }
}

void DviPath::open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
                   const RunWatch& watch) {
  columns_->open(pipeservers, timeout, watch);
  unseen_ = true;  // the first frames are still to be taken in
}

std::optional<PathSwap> DviPath::step(int, PipeserverSet& pipeservers,
                                      std::vector<FrameRecord>& records, const RunWatch& watch) {
  if (refresh_hz_ > 0) clock_.wait_next();
  watch.processes();
  const bool fresh = columns_->take_in(pipeservers) || std::exchange(unseen_, false);
  pipeservers.serve_channels();
  if (balance_) balance_->serve(pipeservers);
  // As fast as possible still means "when there is something to do": re-reading unchanged
  // links would only take CPU from the pipeservers.
  if (refresh_hz_ == 0 && !fresh && !swap_due_) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    return std::nullopt;
  }
  const auto t0 = RunClock::now();
  refresh(pipeservers);
  const double route_ms = ms_between(t0, RunClock::now());
  if (!swapped_.empty()) note_swap();
  // A column rank lost during the refresh is named now, with the frame the displays keep, and
  // before READY is sent: MPI traffic to a rank that is gone ends this process.
  watch.processes();
  record_new_frames(pipeservers, records, decision_.kinds, stamps_, refreshes_ - 1, t0, route_ms);
  swap_due_ = !decision_.completed_groups.empty();
  if (balance_ && columns_->strips_not_counted().empty()) count_for_balance(pipeservers);
  // READY at once, in the refresh the frame completed (spec §6.4): a pipeserver with its next
  // frame rendered swaps it in now, and it is taken in at the next refresh.
  dropped_readies_ +=
      static_cast<std::uint64_t>(send_readies(decision_.ready_inputs, pipeservers, drop_ready_));
  if (swapped_.empty()) return std::nullopt;
  if (balance_) check_groups_for_balance(pipeservers);
  PathSwap swap;
  swap.time = RunClock::now();
  swap.lowest = *std::min_element(stamp_shown_.begin(), stamp_shown_.end());
  swap.refresh = refreshes_ - 1;
  return swap;
}

Tick DviPath::make_tick(std::int64_t index, const PipeserverSet& pipeservers) {
  Tick tick;
  tick.refresh = index;
  tick.swapped_groups.assign(swapped_.begin(), swapped_.end());
  // Where each pipeserver's stamps are (a balanced run's layouts move them): in the frame it
  // delivers next, and on the displays for its last frame and the one before; the displays show
  // one.
  accepted_.clear();
  for (const LivePipeserver& h : pipeservers.all()) {
    // A lost pipeserver's input carries no signal from now on: it feeds no group, holds none up.
    tick.sequences.push_back(h.lost ? kNoSignal : h.sequence);
    tick.stamps.push_back({h.stamp(h.accepted + 1), h.stamp(h.accepted), h.stamp(h.accepted - 1)});
    accepted_.push_back(h.accepted);
  }
  return tick;
}

void DviPath::refresh(PipeserverSet& pipeservers) {
  const auto index = static_cast<std::int64_t>(refreshes_++);
  sequencer_.refresh(swapped_);
  const Tick tick = make_tick(index, pipeservers);
  const Status answered = columns_->refresh(
      tick, pipeservers,
      [&](std::span<const Observation> seen) -> const ColumnRoute& {
        return decide(seen, pipeservers);
      },
      // A column that did not answer: the others swapped without it, so what the displays keep
      // is known before the fault is named (the columns' line says it) and they are saved.
      [&](std::span<const Observation> seen) {
        take(seen, pipeservers);
        if (!swapped_.empty()) note_swap();
      });
  if (!answered.ok()) throw RunFault(answered.reason());
  sequencer_.commit(observations_, decision_);
  if (const Status s = lock_check_.check(static_cast<std::uint64_t>(index), displays_shown_);
      !s.ok())
    throw RunFault(s.reason());
  if (quad_) refresh_quad(static_cast<std::uint64_t>(index));
  if (frame_lock_) frame_lock_->refresh(displays_shown_);
  if (packed_) {
    if (const Status s = packed_->check(static_cast<std::uint64_t>(index), displays_shown_);
        !s.ok())
      throw RunFault(s.reason());
  }
}

void DviPath::refresh_quad(std::uint64_t index) {
  // The columns' pictures only when some display took in a new eye frame (fetched from far
  // columns over MPI), once for all displays.
  std::optional<DisplayPictures> fetched;
  quad_->refresh(index, displays_shown_, [&](int id) -> const RgbImage& {
    if (!fetched) fetched = columns_->pictures();
    return (*fetched)(id);
  });
  if (const Status s = active_check_->check(index, quad_->shown()); !s.ok())
    throw RunFault(s.reason());
}

const ColumnRoute& DviPath::decide(std::span<const Observation> seen,
                                   const PipeserverSet& pipeservers) {
  take(seen, pipeservers);
  sequencer_.decide(observations_, decision_);
  route_.route = decision_.route;
  route_.completed_groups = decision_.completed_groups;
  return route_;
}

void DviPath::take(std::span<const Observation> seen, const PipeserverSet& pipeservers) {
  const std::size_t count = pipeservers.all().size();
  observations_.assign(static_cast<std::size_t>(sequencer_.input_count()), FrameObservation{});
  stamps_.assign(observations_.size(), -1);
  displays_shown_.clear();
  // By pipeserver: the stamps of its frames the displays show, at its last frame's and the one
  // before's.
  std::vector<int> seen_last(count, kStampNotHere), seen_before(count, kStampNotHere);
  const auto pipeserver_of = [](int pipeserver, std::size_t size) {
    if (pipeserver < 0 || static_cast<std::size_t>(pipeserver) >= size)
      throw RunFault(fmt::format("a board column named pipeserver {}", pipeserver));
    return static_cast<std::size_t>(pipeserver);
  };
  for (const Observation& o : seen) {
    for (const InputSeen& i : o.inputs) {
      const std::size_t p = pipeserver_of(i.pipeserver, observations_.size());
      // Each column sees the strips for its own displays: together, every display fed.
      const std::uint64_t fed =
          observations_[p].groups_fed | groups_of_displays(o.mesh, i.displays_fed);
      observations_[p] = {i.present, i.idle, i.torn, i.parity, fed};
      stamps_[p] = i.stamp;
    }
    for (const StampsShown& s : o.stamps) {
      const std::size_t p = pipeserver_of(s.pipeserver, count);
      if (s.last != kStampNotHere) seen_last[p] = s.last;
      if (s.before != kStampNotHere) seen_before[p] = s.before;
    }
    displays_shown_.insert(displays_shown_.end(), o.displays.begin(), o.displays.end());
  }
  // Pipeservers on no answering column, and those lost, stay INT_MAX.
  stamp_shown_.assign(count, INT_MAX);
  for (std::size_t i = 0; i < count; ++i) {
    if (pipeservers.all()[i].lost) continue;
    if (const auto f = shown_by_stamps(accepted_[i], seen_last[i], seen_before[i]))
      stamp_shown_[i] = *f;
  }
}

void DviPath::note_swap() {
  // Pipeservers on no answering column are INT_MAX: the frame kept is that of the displays left.
  const int lowest = *std::min_element(stamp_shown_.begin(), stamp_shown_.end());
  if (lowest == INT_MAX) return;
  shown_ = std::min(lowest, frames_ - 1);
  columns_->showing(shown_);
}

std::uint64_t DviPath::groups_of_displays(int mesh, std::uint64_t displays) const {
  std::uint64_t groups = 0;
  if (mesh < 0 || static_cast<std::size_t>(mesh) >= group_of_display_.size()) return groups;
  for (const auto& [id, group] : group_of_display_[static_cast<std::size_t>(mesh)]) {
    if (displays >> id & 1) groups |= std::uint64_t{1} << group;
  }
  return groups;
}

Status DviPath::failure_as_cause(int, const std::string&) {
  if (const auto gone = columns_->gone()) return Failure{*gone};
  return {};
}

void DviPath::finish() {
  columns_->finish();
  // The displays refresh on once the last eye frame is in, until its pair has been shown to
  // both eyes (at most three refreshes: to the next left-eye one, then its right). They are
  // the quad buffer's alone: the columns have ended, the swap-lock count stays theirs.
  std::uint64_t index = refreshes_;
  for (int more = 0; quad_ && quad_->waiting() && more < 3; ++more) {
    if (refresh_hz_ > 0) clock_.wait_next();
    refresh_quad(index++);
  }
  finished_ = true;
}

void DviPath::add_totals(RunTotals& totals) const {
  totals.refreshes = refreshes_;
  totals.dropped_readies += dropped_readies_;
  columns_->add_totals(totals);
  totals.pace = fmt::format("{} refreshes at {}", refreshes_,
                            refresh_hz_ > 0 ? fmt::format("{:g} Hz", refresh_hz_) : "full speed");
  totals.path_lines += fmt::format(
      "emulator: {} input frames predicted from their input's last layout, {} of them found "
      "different and parsed\n",
      totals.frames_predicted, totals.predictions_missed);
  totals.path_lines += summary_lines();
  if (frame_lock_) {
    totals.path_lines += frame_lock_->summary_lines();
    totals.path_files.emplace_back("frame-lock.csv", frame_lock_->csv());
  }
  if (active_check_) totals.path_files.emplace_back("stereo-refreshes.csv", active_check_->csv());
}

std::string DviPath::summary_lines() const {
  if (!finished_) return {};
  const std::string stereo =
      eye_pairs_ == 0 ? ""
                      : fmt::format(
                            "stereo: both eyes of {} display pair(s) showed the same frame "
                            "in all {} refreshes\n",
                            eye_pairs_, refreshes_);
  return fmt::format(
             "swap lock: every display of each of {} group(s) showed the same frame in all {} "
             "refreshes, {}\n",
             groups_.size(), refreshes_, columns_->where()) +
         stereo + active_stereo_line() + (packed_ ? packed_->summary_line(refreshes_) : "") +
         columns_->summary_lines();
}

std::string DviPath::active_stereo_line() const {
  if (!active_check_) return {};
  return fmt::format(
      "active stereo: {} refreshes, every display alternated left/right every refresh from "
      "its first pair (refresh {}) on; pairs shown: {} ({} repeated: no new pair ready), "
      "broken: 0; quad buffers: {:.1f} MiB{}\n",
      active_check_->refreshes(), active_check_->first_pair(), active_check_->pairs_shown(),
      active_check_->pairs_repeated(),
      static_cast<double>(quad_->buffer_bytes()) / (1024.0 * 1024.0),
      active_check_->csv_cut()
          ? fmt::format("; stereo-refreshes.csv holds the first {}", kMaxStereoRefreshRows)
          : std::string());
}

void DviPath::follow_layouts(LiveBalance& balance, PipeserverSet&) {
  balance_ = &balance;
  if (const std::string why = columns_->strips_not_counted(); !why.empty())
    balance.strips_not_counted(why);
}

void DviPath::count_for_balance(PipeserverSet& pipeservers) {
  std::vector<std::uint64_t> routed(pipeservers.all().size(), 0);
  for (std::size_t i = 0; i < routed.size() && i < decision_.kinds.size(); ++i) {
    if (decision_.kinds[i] != FrameKind::New) continue;
    if (const auto strips = columns_->routed_strips(static_cast<int>(i))) routed[i] = *strips;
  }
  balance_->count_strips(pipeservers, routed);
}

// Each group swapped in this refresh: the frames its displays show, by the stamps on them, must
// share a layout.
void DviPath::check_groups_for_balance(const PipeserverSet& pipeservers) {
  for (const int g : swapped_) {
    balance_->check_swap(groups_[static_cast<std::size_t>(g)].displays, pipeservers,
                         [&](const LivePipeserver& h) {
                           return stamp_shown_[static_cast<std::size_t>(h.pipeserver)];
                         });
  }
}

}  // namespace l2
