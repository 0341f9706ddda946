// The active stereo line of a live run's summary (DviPath::active_stereo_line), its figures read
// so a test can assert them: one implementation for the one-machine and the MPI stereo tests.
#pragma once

#include <optional>
#include <regex>
#include <string>

namespace l2::testing_support {

struct ActiveStereoSummary {
  long refreshes = 0, first_pair = 0, shown = 0, repeated = 0;
};

inline std::optional<ActiveStereoSummary> active_stereo_summary(const std::string& output) {
  static const std::regex line(
      "active stereo: ([0-9]+) refreshes, every display alternated left/right every refresh "
      "from its first pair \\(refresh ([0-9]+)\\) on; pairs shown: ([0-9]+) \\(([0-9]+) "
      "repeated: no new pair ready\\), broken: 0; quad buffers: [0-9.]+ MiB\n");
  std::smatch m;
  if (!std::regex_search(output, m, line)) return std::nullopt;
  return ActiveStereoSummary{std::stol(m[1]), std::stol(m[2]), std::stol(m[3]), std::stol(m[4])};
}

}  // namespace l2::testing_support
