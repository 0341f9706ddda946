#include "report_plot.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/child_process.hpp"
#include "command_line/size_text.hpp"

namespace l2 {
namespace {

// gnuplot on PATH; throws when there is none.
std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  for (const std::string& dir : list_items(path ? path : "", ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / "gnuplot";
    if (!dir.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  throw std::runtime_error("gnuplot is not on PATH (Debian package gnuplot-nox)");
}

// The header and the first row.
std::vector<std::string> first_lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines(2);
  std::getline(in, lines[0]);
  std::getline(in, lines[1]);
  return lines;
}

// The summary's "limited by ..." line, or empty.
std::string limit_of(const std::filesystem::path& summary) {
  std::ifstream in(summary);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("limited by ", 0) == 0) return line;
  }
  return {};
}

// gnuplot's single-quoted string: a quote is written twice.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string colour(std::size_t curve) {
  return kPlotColours[curve % std::size(kPlotColours)];
}

// The plot commands: route_ms (column 5), swap_ms (6), render_ms_<i> (7 + 3i); without an
// emulator (the vizserver path: those columns empty) only the render times.
std::string script(const std::filesystem::path& csv, const std::filesystem::path& png,
                   std::size_t pipeservers, bool emulator, const std::string& title) {
  std::vector<std::string> curves;
  if (emulator) {
    curves.push_back(
        fmt::format("'' using 1:5 with linespoints lw 2 lc rgb '{}' title 'route "
                    "(emulator)'",
                    colour(0)));
    curves.push_back(
        fmt::format("'' using 1:6 with linespoints lw 2 lc rgb '{}' title 'swap "
                    "(input taken in to displays swapped)'",
                    colour(1)));
  }
  for (std::size_t i = 0; i < pipeservers; ++i) {
    curves.push_back(
        fmt::format("'' using 1:{} with linespoints lw 2 lc rgb '{}' title 'render, "
                    "pipeserver {}'",
                    7 + 3 * i, colour(2 + i), i));
  }
  std::string text = fmt::format(
      "set terminal pngcairo size 1000,600 font ',11'\n"
      "set output {}\n"
      "set datafile separator ','\n"
      "set title {}\n"
      "set xlabel 'frame'\n"
      "set ylabel 'ms'\n"
      "set key below\n"
      "set grid\n"
      "set yrange [0:*]\n"
      "plot ",
      quoted(png.string()), quoted(title));
  for (std::size_t i = 0; i < curves.size(); ++i) {
    // The first curve names the file; '' repeats it.
    if (i == 0) curves[i] = quoted(csv.string()) + curves[i].substr(2);
    text += (i ? ", \\\n     " : "") + curves[i];
  }
  return text + "\n";
}

}  // namespace

std::filesystem::path plot_report(const std::filesystem::path& run_dir) {
  const auto csv = run_dir / "report.csv";
  const std::vector<std::string> lines = first_lines(csv);
  const std::string& header = lines[0];
  if (header.empty()) throw std::runtime_error(csv.string() + ": cannot read, or empty");
  const std::string known = "frame,in_refresh,swap_refresh,latency_frames,route_ms,swap_ms";
  const std::vector<std::string> columns = list_items(header);
  if (header.rfind(known, 0) != 0 || (columns.size() - 6) % 3 != 0) {
    throw std::runtime_error(
        fmt::format("{}:1: not the header of an l2wall run's report: {}", csv.string(), header));
  }
  const std::size_t pipeservers = (columns.size() - 6) / 3;
  const std::string limit = limit_of(run_dir / "summary.txt");
  const std::string title = fmt::format("l2wall run, {} pipeservers: time per frame{}", pipeservers,
                                        limit.empty() ? "" : " - " + limit);
  const std::vector<std::string> first_row = list_items(lines[1]);
  const bool emulator = first_row.size() > 4 && !first_row[4].empty();
  const auto png = run_dir / "report.png", commands = run_dir / "report.gnuplot";
  if (!(std::ofstream(commands) << script(csv, png, pipeservers, emulator, title)).flush())
    throw std::runtime_error(commands.string() + ": cannot write");
  std::filesystem::remove(png);
  ChildProcess gnuplot({find_gnuplot(), commands.string()});
  const auto status = gnuplot.wait_for(std::chrono::seconds(60));
  if (!status || !status->ok() || !std::filesystem::exists(png)) {
    throw std::runtime_error(fmt::format("gnuplot {} {}", commands.string(),
                                         status ? status->describe() : "took over 60 s"));
  }
  return png;
}

}  // namespace l2
