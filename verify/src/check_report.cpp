#include "verify/check_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "strip_headers/strip_header.hpp"

namespace l2 {
namespace {

// The parser's error kinds that are not zero, "3 check errors, 1 truncated strip".
std::string refused_strips(const InputCheck& input) {
  std::vector<std::string> parts;
  auto add = [&](std::uint64_t n, const char* what) {
    if (n != 0) parts.push_back(fmt::format("{} {}", n, what));
  };
  add(input.errors.check_errors, "check-bit errors");
  add(input.errors.ext_unsupported, "unsupported EXT strips");
  add(input.errors.zero_width, "zero-width strips");
  add(input.errors.truncations, "truncated strips");
  if (input.to_absent_display != 0) {
    parts.push_back(
        fmt::format("{} pixels sent to displays the wall does not have", input.to_absent_display));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::string frames_line(const RoutingCheck& check) {
  const int given = static_cast<int>(check.inputs.size());
  if (given < check.planned_inputs) {
    const std::string absent = given + 1 == check.planned_inputs
                                   ? fmt::format("input {}", given)
                                   : fmt::format("inputs {}-{}", given, check.planned_inputs - 1);
    return fmt::format("frames given for {} of the wall's {} pipeservers: {} sent nothing", given,
                       check.planned_inputs, absent);
  }
  return fmt::format("{} frames given, the wall has {} pipeservers", given, check.planned_inputs);
}

}  // namespace

std::string display_summary(const DisplayCheck& d) {
  return fmt::format(
      "display {} ({}x{}) {}: {} planned pixels: {} right, {} missing, {} misplaced; {} written "
      "twice, {} behind mullions",
      d.display, d.width, d.height, d.clean() ? "right" : "wrong", d.planned, d.right, d.missing,
      d.misplaced, d.written_twice, d.behind_mullions);
}

std::string describe_run(const MisplacedRun& run) {
  const std::string rows =
      run.rows == 1 ? fmt::format("row {}", run.source_row)
                    : fmt::format("rows {}-{}", run.source_row, run.source_row + run.rows - 1);
  const auto header = decode(run.header);
  const std::string where = run.belongs
                                ? fmt::format("belong on display {} at {},{}", run.belongs->display,
                                              run.belongs->x, run.belongs->y)
                                : std::string("show no test pattern");
  return fmt::format(
      "input {} {} from column {} (header {:012x} {}): {}x{} pixels landed on display {} at "
      "{},{}, {}",
      run.input, rows, run.source_x, run.header, header ? to_string(*header) : "?", run.width,
      run.rows, run.landed.display, run.landed.x, run.landed.y, where);
}

std::vector<std::string> check_report(const RoutingCheck& check, int max_runs) {
  std::vector<std::string> lines;
  for (const DisplayCheck& d : check.displays) lines.push_back(display_summary(d));
  for (const InputCheck& i : check.inputs) {
    if (!i.clean()) lines.push_back(fmt::format("input {}: {}", i.input, refused_strips(i)));
  }
  if (static_cast<int>(check.inputs.size()) != check.planned_inputs) {
    lines.push_back(frames_line(check));
  }
  const int runs = static_cast<int>(check.misplaced.size());
  if (runs > 0) lines.push_back(fmt::format("misplaced runs: {}", runs));
  for (int i = 0; i < std::min(runs, max_runs); ++i) {
    lines.push_back("  " + describe_run(check.misplaced[i]));
  }
  if (runs > max_runs) lines.push_back(fmt::format("  ... and {} more", runs - max_runs));
  const auto wrong = std::count_if(check.displays.begin(), check.displays.end(),
                                   [](const DisplayCheck& d) { return !d.clean(); });
  const auto refused = std::count_if(check.inputs.begin(), check.inputs.end(),
                                     [](const InputCheck& i) { return !i.clean(); });
  if (check.clean()) {
    lines.push_back(fmt::format("routing right: every planned pixel in place on {} display{}",
                                check.displays.size(), check.displays.size() == 1 ? "" : "s"));
  } else {
    lines.push_back(
        fmt::format("routing wrong: {} of {} displays wrong, {} inputs with refused "
                    "strips",
                    wrong, check.displays.size(), refused));
  }
  return lines;
}

}  // namespace l2
