// `l2wall plot DIR` and `l2wall run --plot`: a run's report.csv drawn as DIR/report.png with
// gnuplot (Debian package gnuplot-nox): per frame, the route and swap time of the emulator and
// the render time of every pipeserver, titled with what limited the run (summary.txt).
#pragma once

#include <filesystem>

namespace l2 {

// The line colours, in the order the curves are drawn: route, swap, then pipeserver 0, 1, ...
// (the colours repeat after the last).
inline constexpr const char* kPlotColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                               "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// Writes DIR/report.gnuplot and DIR/report.png; returns the PNG's path. Throws
// std::runtime_error in one line: no report.csv, a header it does not know, gnuplot missing or
// failing.
std::filesystem::path plot_report(const std::filesystem::path& run_dir);

}  // namespace l2
