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
  std::vector<std::string> places;
  for (const RefusedAt& r : input.refused)
    places.push_back(fmt::format("row {} column {} ({})", r.row, r.column, r.why));
  if (places.size() > 3) places.resize(3);
  if (!places.empty())
    parts.push_back(fmt::format("refused at {}{}", fmt::join(places, ", "),
                                input.refused.size() > places.size() ? ", ..." : ""));
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::string fields(const std::optional<StripHeader>& h) {
  if (!h) return "nothing";
  return fmt::format("d={} x={} y={} w={}", h->display, h->x, h->y, h->width);
}

// The lines of an input that is not as its pipeserver's plan says: another size, crossed
// cables or other strips, a torn frame.
void plan_lines(const InputCheck& i, std::vector<std::string>& lines) {
  if (i.size_differs()) {
    lines.push_back(
        fmt::format("input {}: frame {}x{}, but pipeserver {}'s framebuffer is {}x{} (a frame of "
                    "another wall?)",
                    i.input, i.width, i.height, i.input, i.planned_width, i.planned_height));
  }
  if (i.carries) {
    lines.push_back(fmt::format(
        "input {} carries pipeserver {}'s frame, not its own: a crossed cable (on a Lightning-2 "
        "READY goes to the wrong pipeserver, and the bus order changes where strips overlap)",
        i.input, *i.carries));
  } else if (i.not_as_planned != 0 && i.first_difference) {
    const StripDifference& d = *i.first_difference;
    lines.push_back(fmt::format(
        "input {}: {} strip{} not as planned for pipeserver {}, first at row {} column {}: found "
        "{}, planned {}",
        i.input, i.not_as_planned, i.not_as_planned == 1 ? "" : "s", i.input, d.row, d.column,
        fields(d.found), fields(d.planned)));
  }
  if (i.parity == kMixedParity) {
    lines.push_back(fmt::format(
        "input {}: rows of both frame parities, a torn frame (spec §6: a frame has one)", i.input));
  }
}

// "f=0 on inputs 0, 2; f=1 on input 1".
std::string parities(const RoutingCheck& check) {
  std::vector<std::string> parts;
  for (const int p : {0, 1}) {
    std::vector<int> on;
    for (const InputCheck& i : check.inputs)
      if (i.parity == p) on.push_back(i.input);
    if (!on.empty())
      parts.push_back(
          fmt::format("f={} on input{} {}", p, on.size() == 1 ? "" : "s", fmt::join(on, ", ")));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
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
    if (i.refused_strips())
      lines.push_back(fmt::format("input {}: {}", i.input, refused_strips(i)));
    plan_lines(i, lines);
  }
  if (check.parity_differs) {
    lines.push_back(fmt::format(
        "frame parity differs between inputs: {} (spec §6: the frames routed together carry one)",
        parities(check)));
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
                                     [](const InputCheck& i) { return i.refused_strips(); });
  const auto unplanned = std::count_if(check.inputs.begin(), check.inputs.end(),
                                       [](const InputCheck& i) { return !i.as_planned(); });
  const auto torn = std::count_if(check.inputs.begin(), check.inputs.end(),
                                  [](const InputCheck& i) { return i.parity == kMixedParity; });
  if (check.clean()) {
    lines.push_back(fmt::format("routing right: every planned pixel in place on {} display{}",
                                check.displays.size(), check.displays.size() == 1 ? "" : "s"));
  } else {
    std::string verdict =
        fmt::format("routing wrong: {} of {} displays wrong, {} inputs with refused strips", wrong,
                    check.displays.size(), refused);
    if (unplanned != 0) verdict += fmt::format(", {} not as planned", unplanned);
    if (torn != 0) verdict += fmt::format(", {} torn", torn);
    if (check.parity_differs) verdict += ", frame parity differs";
    lines.push_back(verdict);
  }
  return lines;
}

}  // namespace l2
