#include "mpi_traffic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <thread>

#include "l2wall/run_fault.hpp"
#include "l2wall/run_time.hpp"
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

}  // namespace

void MpiTraffic::take_done(const RankMap& map, std::span<const int> gone) {
  const auto deadline = RunClock::now() + std::chrono::seconds(10);
  for (int s = 0; s < map.pipeservers; ++s) {
    if (std::find(gone.begin(), gone.end(), s) != gone.end()) continue;
    const int rank = map.pipeserver_rank(s);
    while (!mpi_wire::waiting(rank, mpi_wire::kDone)) {
      if (RunClock::now() > deadline)
        throw RunFault(
            fmt::format("pipeserver {} (rank {}) did not end after the last frame", s, rank));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const mpi_wire::Record done = mpi_wire::receive(rank, mpi_wire::kDone);
    mpi_wire::Reader in(done);
    for (SentBytes* b : {&frames_, &tiles_}) {
      b->raw += static_cast<std::uint64_t>(in.next());
      b->wire += static_cast<std::uint64_t>(in.next());
      b->first_wire += static_cast<std::uint64_t>(in.next());
    }
  }
}

std::string MpiTraffic::lines(std::uint64_t control_bytes, int frames) const {
  const double n = frames > 0 ? frames : 1;
  std::string out = fmt::format(
      "network: {} of DVI frames (each to the columns it feeds); {:.2f} KB a frame of refresh "
      "records between the coordinator and the columns\n",
      sent_text(frames_, n), static_cast<double>(control_bytes) / n / 1e3);
  if (tiles_.raw > 0)
    out +=
        fmt::format("network: {} of tiles to the columns (vizserver path)\n", sent_text(tiles_, n));
  return out;
}

}  // namespace l2
