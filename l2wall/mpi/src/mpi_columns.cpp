#include "mpi_columns.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <thread>

#include "column_messages.hpp"
#include "l2wall/run_fault.hpp"
#include "mpi_link/mpi_wire.hpp"

namespace l2 {

using mpi_wire::Record;

MpiColumns::MpiColumns(const TileLayout& layout, const RankMap& map, MpiSession& session,
                       const RunOptions& o)
    : layout_(layout),
      map_(map),
      session_(session),
      losses_(map, session, run_balance(o, layout.wall).survive_host_loss),
      stall_timeout_ms_(o.stall_timeout_ms),
      frames_(o.frames) {}

bool MpiColumns::take_in(PipeserverSet& pipeservers) {
  bool fresh = false;
  for (LivePipeserver& h : pipeservers.serving()) {
    const int rank = map_.pipeserver_rank(h.pipeserver);
    while (mpi_wire::waiting(rank, mpi_wire::kNotice)) {
      const Record notice = mpi_wire::receive(rank, mpi_wire::kNotice);
      h.sequence = static_cast<std::uint64_t>(mpi_wire::Reader(notice).next());
      fresh = true;
    }
  }
  return fresh;
}

void MpiColumns::open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
                      const RunWatch& watch) {
  const auto deadline = RunClock::now() + timeout;
  const auto& all = pipeservers.all();
  // As on one machine: the refreshes start once every input carries a signal (a pipeserver
  // lost before its first frame never will).
  const auto silent = [](const LivePipeserver& h) { return !h.lost && h.sequence == 0; };
  for (;;) {
    watch.processes();
    take_in(pipeservers);
    if (std::none_of(all.begin(), all.end(), silent)) return;
    if (RunClock::now() > deadline) {
      std::string missing;
      for (const LivePipeserver& h : all)
        if (silent(h)) missing += fmt::format(" {}", h.pipeserver);
      throw RunFault(fmt::format("no first frame within {} ms from pipeserver(s){}",
                                 timeout.count(), missing));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

Status MpiColumns::refresh(const Tick& tick, PipeserverSet& pipeservers, const Decide& decide,
                           const std::function<void(std::span<const Observation>)>& took) {
  const Record record = encode(tick);
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send(record, map_.column_rank(c), mpi_wire::kCommand);
  control_bytes_ += record.size() * sizeof(std::int64_t) * static_cast<std::size_t>(map_.columns);
  // A column that failed: the others still answer (they swapped with it).
  std::optional<int> failed;
  seen_.clear();
  for (int c = 0; c < map_.columns; ++c) {
    const std::optional<Record> got = answer(c, pipeservers);
    if (!got) {
      if (!failed) failed = c;
      continue;
    }
    control_bytes_ += got->size() * sizeof(std::int64_t);
    Observation& o = seen_.emplace_back(decode_observation(*got));
    if (o.refresh != tick.refresh)
      throw RunFault(fmt::format("{} answered another refresh", map_.role(map_.column_rank(c))));
    for (DisplayShown& d : o.displays) d.rank = map_.column_rank(c);  // the answer's sender
  }
  if (failed) {
    took(seen_);
    return Failure{failure(*failed, tick.refresh)};  // names the frame kept now
  }
  const Record route = encode(decide(seen_));
  for (int c = 0; c < map_.columns; ++c)
    mpi_wire::send(route, map_.column_rank(c), mpi_wire::kCommand);
  control_bytes_ += route.size() * sizeof(std::int64_t) * static_cast<std::size_t>(map_.columns);
  return {};
}

std::optional<Record> MpiColumns::answer(int c, PipeserverSet& pipeservers) {
  const int rank = map_.column_rank(c);
  const auto deadline = RunClock::now() + std::chrono::milliseconds(stall_timeout_ms_);
  // Only this column's own loss ends the wait: a pipeserver gone is taken up after this
  // refresh, once the frame the displays keep is known.
  struct Failed {};
  try {
    return mpi_wire::receive_watched(rank, mpi_wire::kObservation, [&] {
      if (losses_.poll() == rank) throw Failed{};  // and tells the columns of losses survived
      pipeservers.serve_channels();
      if (RunClock::now() < deadline) return;
      stuck_ = rank;
      throw Failed{};
    });
  } catch (const Failed&) {
    return std::nullopt;
  }
}

std::string MpiColumns::failure(int c, std::int64_t refresh) const {
  const int rank = map_.column_rank(c);
  if (losses_.ending() == rank) return losses_.message(rank);
  const auto& who = session_.identities()[static_cast<std::size_t>(rank)];
  return fmt::format(
      "{} (rank {} on {}, pid {}) did not answer refresh {} within {} ms (stopped or hung) "
      "while the displays wait for frame {}; {}",
      map_.role(rank), rank, who.host, who.pid, refresh, stall_timeout_ms_, losses_.shown() + 1,
      losses_.displays_showing());
}

std::optional<std::string> MpiColumns::gone() {
  if (const auto rank = losses_.poll()) return losses_.message(*rank);
  return std::nullopt;
}

void MpiColumns::fetch(std::optional<std::chrono::milliseconds> grace) {
  const auto answering = [&](int rank) {
    return !grace || (losses_.ending() != rank && stuck_ != rank);  // else lost with it
  };
  for (int c = 0; c < map_.columns; ++c) {  // all asked first: they answer side by side
    if (answering(map_.column_rank(c)))
      mpi_wire::send({mpi_wire::kFetch}, map_.column_rank(c), mpi_wire::kCommand);
  }
  for (int c = 0; c < map_.columns; ++c) {
    const int rank = map_.column_rank(c);
    if (!answering(rank)) continue;
    for (const int id : map_.displays_of_column[static_cast<std::size_t>(c)]) {
      const auto deadline = RunClock::now() + grace.value_or(std::chrono::milliseconds(0));
      while (grace && !mpi_wire::waiting(rank, mpi_wire::kPicture) && RunClock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (grace && !mpi_wire::waiting(rank, mpi_wire::kPicture)) break;  // not saved
      const auto d = std::find_if(layout_.wall.displays.begin(), layout_.wall.displays.end(),
                                  [id](const Display& x) { return x.id == id; });
      RgbImage& picture = pictures_[id];
      if (picture.empty()) picture = RgbImage(d->width, d->height);
      mpi_wire::receive_bytes(picture.bytes(), rank, mpi_wire::kPicture);
    }
  }
}

DisplayPictures MpiColumns::pictures() {
  fetch(std::nullopt);
  return [this](int id) -> const RgbImage& { return pictures_.at(id); };
}

std::optional<DisplayPictures> MpiColumns::shown() {
  // Asked after a fault (and only then: the coordinator shows nothing under --mpi): what the
  // columns still answering show now.
  if (!fetched_after_fault_ && !ended_) {
    fetched_after_fault_ = true;
    losses_.stop_watching();  // the fault is named: later losses are its effects
    pictures_.clear();        // a kept frame's: not what a column that is gone showed last
    try {
      fetch(std::chrono::milliseconds(300));
    } catch (const std::runtime_error&) {
      // a column that is gone between the fault and the fetch: its displays are not saved
    }
  }
  if (pictures_.empty()) return std::nullopt;
  return [this](int id) -> const RgbImage& {
    static const RgbImage lost;
    const auto it = pictures_.find(id);
    return it == pictures_.end() ? lost : it->second;
  };
}

void MpiColumns::finish() {
  traffic_.take_done(map_, losses_.survived());
  end_columns();
}

void MpiColumns::end_columns() {
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

}  // namespace l2
