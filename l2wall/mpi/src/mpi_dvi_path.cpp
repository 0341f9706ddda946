#include "mpi_dvi_path.hpp"
#include "lightning2_emu/wall_emulator.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <thread>
#include <utility>

#include "column_messages.hpp"
#include "l2wall/live_balance.hpp"
#include "l2wall/local_lightning2.hpp"
#include "l2wall/run_fault.hpp"
#include "mpi_link/mpi_dvi_link.hpp"
#include "mpi_link/mpi_wire.hpp"

namespace l2 {
namespace {

// "0.188 MB a frame on the wire (5.760 MB raw, 30.6x less; the first 0.95 MB, then 0.15 MB a
// frame)": the first frame starts from black, what comes after is what a scene costs.
std::string sent_text(const SentBytes& b, double frames) {
  const double mb = 1e6;
  const double after = frames > 1 ? static_cast<double>(b.wire - b.first_wire) / (frames - 1) : 0;
  return fmt::format(
      "{:.3f} MB a frame on the wire ({:.3f} MB raw, {:.1f}x less; the first "
      "{:.3f} MB, then {:.3f} MB a frame)",
      static_cast<double>(b.wire) / frames / mb, static_cast<double>(b.raw) / frames / mb,
      b.wire > 0 ? static_cast<double>(b.raw) / static_cast<double>(b.wire) : 0.0,
      static_cast<double>(b.first_wire) / mb, after / mb);
}

using mpi_wire::Reader;
using mpi_wire::Record;

std::vector<SwapGroup> wall_groups(const Wall& wall) {
  return make_swap_groups(display_specs(wall));
}

}  // namespace

MpiDviPath::MpiDviPath(const TileLayout& layout, const RankMap& map, MpiSession& session,
                       const RunOptions& o)
    : layout_(layout),
      map_(map),
      session_(session),
      stall_timeout_ms_(o.stall_timeout_ms),
      survive_(run_balance(o, layout.wall).survive_host_loss),
      clock_(o.refresh_hz),
      refresh_hz_(o.refresh_hz),
      frames_(o.frames),
      drop_ready_(o.drop_ready),
      groups_(wall_groups(layout.wall)),
      sequencer_(map.mesh_inputs, static_cast<int>(groups_.size())),
      lock_check_(groups_) {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    for (const int id : groups_[g].displays) group_of_display_[id] = static_cast<int>(g);
  }
  session_.watch_ranks(
      [this](int rank) { return survived(rank) ? std::string() : lost_message(rank); });
}

bool MpiDviPath::survived(int rank) const {
  return survive_ && map_.pipeserver_of(rank).has_value();
}

std::string MpiDviPath::lost_message(int rank) const {
  const auto& who = session_.identities()[static_cast<std::size_t>(rank)];
  return fmt::format(
      "{} (rank {} on {}, pid {}) is gone (its connection to the coordinator closed: killed "
      "or crashed) while the displays wait for frame {}; {}",
      map_.role(rank), rank, who.host, who.pid, shown_ + 1, displays_showing());
}

bool MpiDviPath::take_notices(PipeserverSet& pipeservers) {
  bool fresh = false;
  for (LivePipeserver& h : pipeservers.serving()) {
    const int rank = map_.pipeserver_rank(h.pipeserver);
    while (mpi_wire::waiting(rank, mpi_wire::kNotice)) {
      const Record notice = mpi_wire::receive(rank, mpi_wire::kNotice);
      h.sequence = static_cast<std::uint64_t>(Reader(notice).next());
      fresh = true;
    }
  }
  return fresh;
}

void MpiDviPath::open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
                      const RunWatch& watch) {
  const auto deadline = RunClock::now() + timeout;
  for (;;) {
    watch.processes();
    take_notices(pipeservers);
    const auto& all = pipeservers.all();
    // As on one machine: the refreshes start once every input carries a signal (a pipeserver
    // lost before its first frame never will).
    if (std::all_of(all.begin(), all.end(),
                    [](const LivePipeserver& h) { return h.lost || h.sequence > 0; })) {
      unseen_ = true;  // the first frames are still to be taken in
      return;
    }
    if (RunClock::now() > deadline) {
      std::string missing;
      for (const LivePipeserver& h : all)
        if (!h.lost && h.sequence == 0) missing += fmt::format(" {}", h.pipeserver);
      throw RunFault(fmt::format("no first frame within {} ms from pipeserver(s){}",
                                 timeout.count(), missing));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

std::uint64_t MpiDviPath::groups_of_displays(std::uint64_t displays) const {
  std::uint64_t groups = 0;
  for (const auto& [id, group] : group_of_display_) {
    if (displays >> id & 1) groups |= std::uint64_t{1} << group;
  }
  return groups;
}

void MpiDviPath::refresh(PipeserverSet& pipeservers) {
  const auto index = static_cast<std::int64_t>(refreshes_++);
  sequencer_.refresh(swapped_);
  Tick tick;
  tick.refresh = index;
  tick.swapped_groups.assign(swapped_.begin(), swapped_.end());
  // Where each pipeserver's stamps are (a balanced run's layouts move them): in the frame it
  // delivers next, and on the displays for its last frame and the one before; the displays show
  // one.
  accepted_.clear();
  for (const LivePipeserver& h : pipeservers.all()) {
    // A lost pipeserver's input carries no signal from now on: it feeds no group, holds none up.
    tick.sequences.push_back(h.lost ? mpi_wire::kNoSignal : h.sequence);
    tick.stamps.push_back({h.stamp(h.accepted + 1), h.stamp(h.accepted), h.stamp(h.accepted - 1)});
    accepted_.push_back(h.accepted);
  }
  const Record record = encode(tick);
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send(record, map_.column_rank(c), mpi_wire::kCommand);
  control_bytes_ += record.size() * sizeof(std::int64_t) * static_cast<std::size_t>(map_.columns);

  observations_.assign(static_cast<std::size_t>(map_.mesh_inputs), FrameObservation{});
  stamps_.assign(static_cast<std::size_t>(map_.mesh_inputs), -1);
  stamp_shown_.assign(pipeservers.all().size(), INT_MAX);
  displays_shown_.clear();
  // A column that failed: the others still answer (they swapped with it), so what the
  // displays keep is known before the fault is named and the displays are saved.
  std::optional<int> column_failed;
  // By pipeserver: its stamps on the displays, of its last frame and of the one before.
  std::vector<int> seen_last(pipeservers.all().size(), mpi_wire::kStampNotHere);
  std::vector<int> seen_before(seen_last);
  for (int c = 0; c < map_.columns; ++c) {
    const int rank = map_.column_rank(c);
    const std::optional<Record> answer = column_answer(c, pipeservers);
    if (!answer) {
      if (!column_failed) column_failed = c;
      continue;
    }
    control_bytes_ += answer->size() * sizeof(std::int64_t);
    const Observation seen = decode_observation(*answer);
    if (seen.refresh != index)
      throw RunFault(fmt::format("{} answered another refresh", map_.role(rank)));
    const auto pipeserver_of = [&](int pipeserver, std::size_t count) {
      if (pipeserver < 0 || static_cast<std::size_t>(pipeserver) >= count)
        throw RunFault(fmt::format("{} named pipeserver {}", map_.role(rank), pipeserver));
      return static_cast<std::size_t>(pipeserver);
    };
    for (const InputSeen& i : seen.inputs) {
      const std::size_t p = pipeserver_of(i.pipeserver, observations_.size());
      FrameObservation& o = observations_[p];
      o.present = i.present;
      o.idle = i.idle;
      o.torn = i.torn;
      o.parity = i.parity;
      // Each column sees the strips for its own displays: together, every display fed.
      o.groups_fed |= groups_of_displays(i.displays_fed);
      stamps_[p] = i.stamp;
    }
    for (const StampsShown& s : seen.stamps) {
      const std::size_t p = pipeserver_of(s.pipeserver, seen_last.size());
      if (s.last != mpi_wire::kStampNotHere) seen_last[p] = s.last;
      if (s.before != mpi_wire::kStampNotHere) seen_before[p] = s.before;
    }
    for (DisplayShown d : seen.displays) {
      d.rank = rank;  // the answer's sender
      displays_shown_.push_back(d);
    }
  }
  // As on one machine (LocalLightning2::frame_shown): the last frame if its stamp says so, else the
  // one before if its stamp says so, else what the last frame's spot shows. Pipeservers on no
  // answering column, and those lost, stay INT_MAX.
  for (std::size_t i = 0; i < stamp_shown_.size(); ++i) {
    if (pipeservers.all()[i].lost) continue;
    const int last = accepted_[i];
    if (last >= 0 && seen_last[i] == last)
      stamp_shown_[i] = last;
    else if (last >= 1 && seen_before[i] == last - 1)
      stamp_shown_[i] = last - 1;
    else if (seen_last[i] != mpi_wire::kStampNotHere)
      stamp_shown_[i] = seen_last[i];
    else if (seen_before[i] != mpi_wire::kStampNotHere)
      stamp_shown_[i] = seen_before[i];
  }
  if (column_failed) {
    if (!swapped_.empty()) note_swap();
    throw RunFault(column_failure(*column_failed, index));  // names the frame kept now
  }
  sequencer_.decide(observations_, decision_);
  sequencer_.commit(observations_, decision_);
  Record route{mpi_wire::kRoute, static_cast<std::int64_t>(decision_.route.size())};
  route.insert(route.end(), decision_.route.begin(), decision_.route.end());
  route.push_back(static_cast<std::int64_t>(decision_.completed_groups.size()));
  route.insert(route.end(), decision_.completed_groups.begin(), decision_.completed_groups.end());
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send(route, map_.column_rank(c), mpi_wire::kCommand);
  control_bytes_ += route.size() * sizeof(std::int64_t) * static_cast<std::size_t>(map_.columns);
  if (const Status s = lock_check_.check(static_cast<std::uint64_t>(index), displays_shown_);
      !s.ok())
    throw RunFault(s.reason());
}

std::optional<Record> MpiDviPath::column_answer(int c, PipeserverSet& pipeservers) {
  const int rank = map_.column_rank(c);
  const auto deadline = RunClock::now() + std::chrono::milliseconds(stall_timeout_ms_);
  // Only this column's own loss ends the wait: a pipeserver gone is taken up after this
  // refresh, once the frame the displays keep is known.
  struct Failed {};
  try {
    return mpi_wire::receive_watched(rank, mpi_wire::kObservation, [&] {
      if (down() && *lost_ == rank) throw Failed{};  // and tells the columns of losses survived
      pipeservers.serve_channels();
      if (RunClock::now() >= deadline) {
        stuck_ = rank;
        throw Failed{};
      }
    });
  } catch (const Failed&) {
    return std::nullopt;
  }
}

std::string MpiDviPath::column_failure(int c, std::int64_t index) const {
  const int rank = map_.column_rank(c);
  if (lost_ == rank) return lost_message(rank);
  const auto& who = session_.identities()[static_cast<std::size_t>(rank)];
  return fmt::format(
      "{} (rank {} on {}, pid {}) did not answer refresh {} within {} ms (stopped or hung) "
      "while the displays wait for frame {}; {}",
      map_.role(rank), rank, who.host, who.pid, index, stall_timeout_ms_, shown_ + 1,
      displays_showing());
}

void MpiDviPath::note_swap() {
  // Pipeservers on no answering column are INT_MAX: the frame kept is that of the displays left.
  const int lowest = *std::min_element(stamp_shown_.begin(), stamp_shown_.end());
  if (lowest != INT_MAX) shown_ = std::min(lowest, frames_ - 1);
}

std::string MpiDviPath::displays_showing() const {
  const int shown = shown_;
  if (shown < 0) return "no frame reached the displays";
  return fmt::format("the displays keep frame {}", shown);
}

bool MpiDviPath::down() {
  // A pipeserver rank the run survives ends as a pipeserver does (PipeserverSet::poll_ended).
  for (const int rank : session_.lost_ranks()) {
    if (lost_) break;
    if (!survived(rank))
      lost_ = rank;
    else
      tell_columns_lost(*map_.pipeserver_of(rank));
  }
  return lost_.has_value();
}

void MpiDviPath::tell_columns_lost(int pipeserver) {
  if (std::find(gone_.begin(), gone_.end(), pipeserver) != gone_.end()) return;
  gone_.push_back(pipeserver);
  // At once, not at the next tick: a column may be waiting for a frame the pipeserver died
  // sending, and this process for that column's answer.
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send({pipeserver}, map_.column_rank(c), mpi_wire::kLost);
}

Status MpiDviPath::failure_as_cause(int, const std::string&) {
  if (!lost_) return {};
  return Failure{lost_message(*lost_)};
}

std::optional<PathSwap> MpiDviPath::step(int, PipeserverSet& pipeservers,
                                         std::vector<FrameRecord>& records, const RunWatch& watch) {
  if (refresh_hz_ > 0) clock_.wait_next();
  watch.processes();
  const bool fresh = take_notices(pipeservers) || std::exchange(unseen_, false);
  pipeservers.serve_channels();
  if (balance_) balance_->serve(pipeservers);
  if (refresh_hz_ == 0 && !fresh && !swap_due_) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    return std::nullopt;
  }
  const auto t0 = RunClock::now();
  refresh(pipeservers);
  if (!swapped_.empty()) note_swap();
  // A rank lost during the refresh is named now, with the frame the displays keep, and before
  // READY is sent: MPI traffic to a rank that is gone ends this process (Open MPI's TCP
  // transport aborts), and the displays would not be saved.
  watch.processes();
  record_new_frames(
      pipeservers, records, decision_.kinds, [&](std::size_t i) { return stamps_[i]; },
      refreshes_ - 1, t0, ms_between(t0, RunClock::now()));
  swap_due_ = !decision_.completed_groups.empty();
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

DisplayPictures MpiDviPath::frame_pictures(int, const RunWatch&) {
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send({mpi_wire::kFetch}, map_.column_rank(c), mpi_wire::kCommand);
  for (int c = 0; c < map_.columns; ++c) {
    for (const int id : map_.displays_of_column[static_cast<std::size_t>(c)]) {
      const auto d = std::find_if(layout_.wall.displays.begin(), layout_.wall.displays.end(),
                                  [id](const Display& x) { return x.id == id; });
      RgbImage& picture = pictures_[id];
      if (picture.empty()) picture = RgbImage(d->width, d->height);
      MPI_Recv(picture.data(), static_cast<int>(picture.bytes().size()), MPI_BYTE,
               map_.column_rank(c), mpi_wire::kPicture, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
  }
  return [this](int id) -> const RgbImage& { return pictures_.at(id); };
}

void MpiDviPath::fetch_answering(std::chrono::milliseconds grace) const {
  pictures_.clear();  // a kept frame's: not what a column that is gone showed last
  for (int c = 0; c < map_.columns; ++c) {
    const int rank = map_.column_rank(c);
    if (lost_ == rank || stuck_ == rank) continue;  // its displays are lost with it
    try {
      mpi_wire::send({mpi_wire::kFetch}, rank, mpi_wire::kCommand);
      for (const int id : map_.displays_of_column[static_cast<std::size_t>(c)]) {
        const auto deadline = RunClock::now() + grace;
        while (!mpi_wire::waiting(rank, mpi_wire::kPicture)) {
          if (RunClock::now() > deadline) throw std::runtime_error("no answer");
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        const auto d = std::find_if(layout_.wall.displays.begin(), layout_.wall.displays.end(),
                                    [id](const Display& x) { return x.id == id; });
        RgbImage picture(d->width, d->height);
        MPI_Recv(picture.data(), static_cast<int>(picture.bytes().size()), MPI_BYTE, rank,
                 mpi_wire::kPicture, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        pictures_[id] = std::move(picture);
      }
    } catch (const std::runtime_error&) {
      // that column's displays are not saved
    }
  }
}

std::optional<DisplayPictures> MpiDviPath::shown() const {
  // Asked after a fault (and only then: the coordinator shows nothing under --mpi): what the
  // columns still answering show now.
  if (!fetched_after_fault_ && !ended_) {
    fetched_after_fault_ = true;
    session_.stop_watching();  // the fault is named: later losses are its effects
    fetch_answering(std::chrono::milliseconds(300));
  }
  // The displays of a column that is gone or stopped are lost with it: empty pictures.
  if (pictures_.empty()) return std::nullopt;
  return [this](int id) -> const RgbImage& {
    static const RgbImage lost;
    const auto it = pictures_.find(id);
    return it == pictures_.end() ? lost : it->second;
  };
}

void MpiDviPath::finish() {
  SentBytes frames_sent, tiles_sent;
  const auto deadline = RunClock::now() + std::chrono::seconds(10);
  for (int s = 0; s < map_.pipeservers; ++s) {
    if (std::find(gone_.begin(), gone_.end(), s) != gone_.end()) continue;  // sends nothing more
    while (!mpi_wire::waiting(map_.pipeserver_rank(s), mpi_wire::kDone)) {
      if (RunClock::now() > deadline)
        throw RunFault(fmt::format("pipeserver {} (rank {}) did not end after the last frame", s,
                                   map_.pipeserver_rank(s)));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const Record done = mpi_wire::receive(map_.pipeserver_rank(s), mpi_wire::kDone);
    Reader in(done);
    for (SentBytes* b : {&frames_sent, &tiles_sent}) {
      b->raw += static_cast<std::uint64_t>(in.next());
      b->wire += static_cast<std::uint64_t>(in.next());
      b->first_wire += static_cast<std::uint64_t>(in.next());
    }
  }
  end_columns();
  std::printf(
      "swap lock: every display of each of %zu group(s) showed the same frame in all %llu "
      "refreshes, over %d board column rank(s)\n",
      groups_.size(), static_cast<unsigned long long>(refreshes_), map_.columns);
  const double frames = frames_ > 0 ? frames_ : 1;
  std::printf(
      "network: %s of DVI frames (each to the columns it feeds); %.2f KB a frame of "
      "refresh records between the coordinator and the columns\n",
      sent_text(frames_sent, frames).c_str(), static_cast<double>(control_bytes_) / frames / 1e3);
  if (tiles_sent.raw > 0)
    std::printf("network: %s of tiles to the columns (vizserver path)\n",
                sent_text(tiles_sent, frames).c_str());
}

void MpiDviPath::end_columns() {
  if (ended_) return;
  ended_ = true;
  for (int c = 0; c < map_.columns; ++c) {
    try {
      mpi_wire::send({mpi_wire::kEnd}, map_.column_rank(c), mpi_wire::kCommand);
    } catch (const std::runtime_error&) {
      // a column that is gone: the fault's MPI_Abort ends what is left
    }
  }
}

// Each group swapped in this refresh: the frames its displays show, by the stamps on them, must
// share a layout (as DviPath checks on one machine).
void MpiDviPath::check_groups_for_balance(const PipeserverSet& pipeservers) {
  for (const int g : swapped_) {
    balance_->check_swap(groups_[static_cast<std::size_t>(g)].displays, pipeservers,
                         [&](const LivePipeserver& h) {
                           return stamp_shown_[static_cast<std::size_t>(h.pipeserver)];
                         });
  }
}

void MpiDviPath::follow_layouts(LiveBalance& balance, PipeserverSet&) {
  balance_ = &balance;
  balance.strips_not_counted("the board column ranks do not count the strips they route");
}

void MpiDviPath::add_totals(RunTotals& totals) const {
  totals.refreshes = refreshes_;
  totals.dropped_readies += dropped_readies_;
}

}  // namespace l2
