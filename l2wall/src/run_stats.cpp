#include "run_stats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace l2 {

std::optional<Spread> spread_of(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  const auto rank = [&](double p) {
    const auto n = static_cast<double>(values.size());
    const auto k = static_cast<std::size_t>(std::ceil(p / 100.0 * n));
    return values[std::max<std::size_t>(k, 1) - 1];
  };
  return Spread{rank(50), rank(95), values.back()};
}

namespace {

std::string spread_text(const Spread& s) {
  return fmt::format("{:.1f} / {:.1f} / {:.1f} ms", s.p50, s.p95, s.max);
}

}  // namespace

std::string spread_lines(const RunTimes& t) {
  std::string lines;
  std::string limit;
  double limit_ms = -1;
  const auto candidate = [&](double median, std::string what) {
    if (median > limit_ms) {
      limit_ms = median;
      limit = std::move(what);
    }
  };
  for (std::size_t i = 0; i < t.render.size(); ++i) {
    const auto s = spread_of(t.render[i]);
    if (!s) continue;
    const bool lost = i < t.lost.size() && t.lost[i];
    lines += fmt::format("render time of pipeserver {} (median / 95th percentile / max): {}{}\n", i,
                         spread_text(*s), lost ? " (lost mid-run)" : "");
    if (!lost)
      candidate(s->p50, fmt::format("pipeserver {}'s render time: median {:.1f} ms", i, s->p50));
  }
  if (const auto s = spread_of(t.route)) {
    lines += fmt::format("route time of the emulator (median / 95th percentile / max): {}\n",
                         spread_text(*s));
    candidate(s->p50, fmt::format("the emulator's route time: median {:.1f} ms", s->p50));
  }
  if (const auto s = spread_of(t.swap)) {
    lines += fmt::format(
        "swap time, input taken in to displays swapped (median / 95th percentile / max): {}\n",
        spread_text(*s));
  }
  if (t.refresh_hz > 0) {
    const double period = 1000.0 / t.refresh_hz;
    candidate(period,
              fmt::format("the refresh rate: {:g} Hz, {:.1f} ms a refresh", t.refresh_hz, period));
  }
  if (limit_ms >= 0) lines += "limited by " + limit + "\n";
  return lines;
}

}  // namespace l2
