#include "column_messages.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tilelayout/wall.hpp"

namespace l2 {
namespace {

using mpi_wire::Reader;
using mpi_wire::Record;

constexpr std::size_t kSpotWords = 5, kPipeserverStampsWords = 3 * kSpotWords;
constexpr std::size_t kInputWords = 7, kStampsShownWords = 3, kDisplayWords = 3;

void put(Record& r, const StampSpot& s) {
  r.insert(r.end(), {s.fb_x, s.fb_y, s.display, s.dx, s.dy});
}

StampSpot take_spot(Reader& in) {
  StampSpot s;
  for (int* field : {&s.fb_x, &s.fb_y, &s.display, &s.dx, &s.dy}) *field = in.next_int();
  return s;
}

}  // namespace

Record encode(const Tick& t) {
  Record r{mpi_wire::kTick, t.refresh, static_cast<std::int64_t>(t.swapped_groups.size())};
  r.insert(r.end(), t.swapped_groups.begin(), t.swapped_groups.end());
  r.push_back(static_cast<std::int64_t>(t.sequences.size()));
  for (const std::uint64_t s : t.sequences) r.push_back(static_cast<std::int64_t>(s));
  r.push_back(static_cast<std::int64_t>(t.stamps.size()));
  for (const PipeserverStamps& h : t.stamps) {
    for (const StampSpot* s : {&h.next, &h.last, &h.before}) put(r, *s);
  }
  return r;
}

Tick decode_tick(Reader& in) {
  Tick t;
  t.refresh = in.next();
  t.swapped_groups.resize(in.count(1));
  for (int& g : t.swapped_groups) g = in.next_int();
  t.sequences.resize(in.count(1));
  for (std::uint64_t& s : t.sequences) s = static_cast<std::uint64_t>(in.next());
  t.stamps.resize(in.count(kPipeserverStampsWords));
  for (PipeserverStamps& h : t.stamps) {
    for (StampSpot* s : {&h.next, &h.last, &h.before}) *s = take_spot(in);
  }
  return t;
}

Record encode(const Observation& o) {
  Record r{o.refresh, o.mesh, static_cast<std::int64_t>(o.inputs.size())};
  for (const InputSeen& i : o.inputs) {
    r.insert(r.end(), {i.pipeserver, i.present, i.idle, i.torn, i.parity,
                       static_cast<std::int64_t>(i.displays_fed), i.stamp});
  }
  r.push_back(static_cast<std::int64_t>(o.stamps.size()));
  for (const StampsShown& s : o.stamps) r.insert(r.end(), {s.pipeserver, s.last, s.before});
  r.push_back(static_cast<std::int64_t>(o.displays.size()));
  for (const DisplayShown& d : o.displays) r.insert(r.end(), {d.display, d.frame, d.oldest});
  return r;
}

Observation decode_observation(const Record& record) {
  Reader in(record);
  Observation o;
  o.refresh = in.next();
  o.mesh = in.next_int();
  if (o.mesh < 0 || o.mesh >= kMaxMeshes)
    throw std::runtime_error(
        fmt::format("an observation of mesh {}, not 0..{}", o.mesh, kMaxMeshes - 1));
  o.inputs.resize(in.count(kInputWords));
  for (InputSeen& i : o.inputs) {
    i.pipeserver = in.next_int();
    i.present = in.next() != 0;
    i.idle = in.next() != 0;
    i.torn = in.next() != 0;
    i.parity = in.next_int();
    i.displays_fed = static_cast<std::uint64_t>(in.next());
    i.stamp = in.next_int();
  }
  o.stamps.resize(in.count(kStampsShownWords));
  for (StampsShown& s : o.stamps) {
    s.pipeserver = in.next_int();
    s.last = in.next_int();
    s.before = in.next_int();
  }
  o.displays.resize(in.count(kDisplayWords));
  for (DisplayShown& d : o.displays) {
    d.display = in.next_int();
    d.frame = in.next_int();
    d.oldest = in.next_int();
  }
  if (!in.done()) throw std::runtime_error("MPI record: words past its last item");
  return o;
}

Record encode(const ColumnRoute& route) {
  Record r{mpi_wire::kRoute, static_cast<std::int64_t>(route.route.size())};
  r.insert(r.end(), route.route.begin(), route.route.end());
  r.push_back(static_cast<std::int64_t>(route.completed_groups.size()));
  r.insert(r.end(), route.completed_groups.begin(), route.completed_groups.end());
  return r;
}

ColumnRoute decode_route(Reader& in) {
  ColumnRoute route;
  route.route.resize(in.count(1));
  for (std::uint8_t& c : route.route) c = static_cast<std::uint8_t>(in.next() != 0);
  route.completed_groups.resize(in.count(1));
  for (int& g : route.completed_groups) g = in.next_int();
  return route;
}

}  // namespace l2
