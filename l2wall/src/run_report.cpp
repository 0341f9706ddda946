#include "l2wall/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "pipeserver_log.hpp"
#include "run_stats.hpp"

namespace l2 {
namespace {

struct PipeserverFrame {
  double render_ms = 0, wait_ms = 0;
  int retries = 0;
  bool logged = false;  // a pipeserver lost mid-run (--survive-host-loss) logs no later frame, nor
                        // one stopped before its line
};
struct PipeserverLog {
  std::vector<PipeserverFrame> frames;
  std::string done;      // the pipeserver's back-channel counts
  std::string renderer;  // what it renders with, and why
};

PipeserverLog read_pipeserver_log(const std::string& path, int frames) {
  PipeserverLog log;
  log.frames.resize(static_cast<std::size_t>(frames));
  std::ifstream in(path);
  std::string text;
  while (std::getline(in, text)) {
    const PipeserverLogLine line = parse_pipeserver_log_line(text);
    if (line.kind == PipeserverLogLine::Kind::Frame && line.frame >= 0 && line.frame < frames) {
      log.frames[static_cast<std::size_t>(line.frame)] = {line.render_ms, line.wait_ms,
                                                          line.retries, true};
    } else if (line.kind == PipeserverLogLine::Kind::Done) {
      log.done = line.done;
    } else if (line.kind == PipeserverLogLine::Kind::Renderer) {
      log.renderer = line.renderer;
    }
  }
  return log;
}

long latency_of(const FrameRecord& r) {
  return static_cast<long>(r.swap_refresh) - static_cast<long>(r.in_refresh);
}

// Frame k's swap time: from its input taken in to the displays swapped, less the time the run was
// paused since the frame before swapped (--show's space, the control page): a pause holds the
// frame back, it is not the emulator's or a pipeserver's time. In a run that keeps up, the frame
// is taken in as the one before swaps, so the pause falls between its input and its swap.
double swap_ms(const std::vector<FrameRecord>& records, std::size_t k) {
  const FrameRecord& r = records[k];
  const double paused = r.paused_ms - (k > 0 ? records[k - 1].paused_ms : 0.0);
  return std::max(0.0, ms_between(r.in_time, r.swap_time) - paused);
}

// `stereo`: an active wall's rows are eye frames, and a last column says which eye.
std::string csv_text(const RunTotals& totals, const std::vector<PipeserverLog>& logs,
                     const std::vector<FrameRecord>& records, const StereoSpec& stereo) {
  const bool dvi = totals.latency_measured;
  const bool eyes = stereo.mode == StereoMode::Active;
  std::string csv = "frame,in_refresh,swap_refresh,latency_frames,route_ms,swap_ms";
  for (std::size_t i = 0; i < logs.size(); ++i)
    csv += fmt::format(",render_ms_{0},ready_wait_ms_{0},sync_retries_{0}", i);
  csv += eyes ? ",eye\n" : "\n";
  for (std::size_t k = 0; k < records.size(); ++k) {
    const FrameRecord& r = records[k];
    if (dvi) {
      csv += fmt::format("{},{},{},{},{:.3f},{:.3f}", k, r.in_refresh, r.swap_refresh,
                         latency_of(r), r.route_ms, swap_ms(records, k));
    } else {
      csv += fmt::format("{},,,n/a,,", k);  // no emulator on the vizserver path
    }
    for (const PipeserverLog& log : logs) {
      const PipeserverFrame& f = log.frames[k];
      if (f.logged) {
        csv += fmt::format(",{:.3f},{:.3f},{}", f.render_ms, f.wait_ms, f.retries);
      } else {
        csv += ",,,";  // no line: its pipeserver was lost (or stopped) before
      }
    }
    if (eyes)
      csv += fmt::format(",{}",
                         kEyeNames[static_cast<int>(frame_eye(stereo, static_cast<int>(k)).eye)]);
    csv += "\n";
  }
  return csv;
}

// The times report.csv holds, for the summary's percentiles.
RunTimes run_times(const RunOptions& o, const RunTotals& totals,
                   const std::vector<PipeserverLog>& logs,
                   const std::vector<FrameRecord>& records) {
  RunTimes t;
  for (const PipeserverLog& log : logs) {
    t.render.emplace_back();
    for (const PipeserverFrame& f : log.frames) {
      if (f.logged) t.render.back().push_back(f.render_ms);
    }
  }
  if (totals.latency_measured) {  // no emulator on the vizserver path
    for (std::size_t k = 0; k < records.size(); ++k) {
      t.route.push_back(records[k].route_ms);
      t.swap.push_back(swap_ms(records, k));
    }
    // With no frame shown (a fault before the first) nothing limited anything.
    if (!records.empty()) t.refresh_hz = o.refresh_hz;
  }
  return t;
}

// The summary's latency line: the frame stamps' latency over the run, or why it was not measured.
std::string latency_line(const std::vector<FrameRecord>& records, const RunTotals& totals) {
  if (records.empty()) return "latency: not measured (no frame reached the displays)\n";
  if (!totals.latency_measured)
    return "latency: not measured on the vizserver path (no DVI link, no refresh)\n";
  long min_latency = 1 << 30, max_latency = -1;
  for (const FrameRecord& r : records) {
    min_latency = std::min(min_latency, latency_of(r));
    max_latency = std::max(max_latency, latency_of(r));
  }
  return fmt::format(
      "latency: {} frame{} (display refresh j shows the input frame taken in at refresh j-1), "
      "measured from the frame stamps routed to the displays: min {}, max {}\n",
      max_latency, max_latency == 1 ? "" : "s", min_latency, max_latency);
}

// What the pipeservers render with: one line when they all decided alike, else a line each.
std::string renderer_lines(const std::vector<PipeserverLog>& logs) {
  if (logs.empty()) return {};
  const auto said = [](const PipeserverLog& log) {
    return log.renderer.empty() ? std::string("not said (it stopped before rendering)")
                                : log.renderer;
  };
  const bool alike = std::all_of(logs.begin(), logs.end(), [&](const PipeserverLog& log) {
    return log.renderer == logs.front().renderer;
  });
  if (alike && logs.front().renderer.empty())
    return "renderer: not said (no pipeserver got as far as rendering)\n";
  if (alike) {
    return fmt::format("renderer: {}{}\n", logs.front().renderer,
                       logs.size() > 1 ? ", on every pipeserver" : "");
  }
  std::string lines;
  for (std::size_t i = 0; i < logs.size(); ++i)
    lines += fmt::format("renderer pipeserver {}: {}\n", i, said(logs[i]));
  return lines;
}

}  // namespace

RunReportTexts run_report(const RunOptions& o, const Wall& wall,
                          const std::vector<std::string>& pipeserver_logs,
                          const std::vector<FrameRecord>& records, const RunTotals& totals,
                          const std::string& extra, const std::string& fault) {
  const int frames = static_cast<int>(records.size());
  std::vector<PipeserverLog> logs;
  for (const std::string& path : pipeserver_logs) logs.push_back(read_pipeserver_log(path, frames));
  const auto csv_path = std::filesystem::path(o.out) / "report.csv";
  // Up to the last swap: writing the saved PNGs afterwards is not part of the frame rate, and
  // neither are --show pauses (the pipeservers wait). Pictures saved during the run are: the
  // pipeservers render the next frame meanwhile, so taking that time out would count their work as
  // free.
  const double seconds =
      records.empty()
          ? 0.0
          : (ms_between(totals.start, records.back().swap_time) - records.back().paused_ms) /
                1000.0;
  const double writing_s = records.empty() ? 0.0 : records.back().writing_ms / 1000.0;
  // A run a fault ended says so first; its figures are those of the frames before the fault.
  std::string summary =
      fault.empty()
          ? std::string("l2wall run: ")
          : fmt::format("l2wall run: ended in a fault at frame {}: {}\nup to the fault: ", frames,
                        fault);
  summary +=
      fmt::format("{} frames on {} displays from {} pipeservers in {:.2f} s: {:.1f} fps ({})\n",
                  frames, wall.displays.size(), pipeserver_logs.size(), seconds,
                  seconds > 0 ? frames / seconds : 0.0, totals.pace);
  if (writing_s >= 0.005) {
    summary += fmt::format(
        "of which {:.2f} s writing the pictures saved during the run (--keep, or Save on the "
        "control page): without them the run would be faster\n",
        writing_s);
  }
  summary += latency_line(records, totals);
  summary += renderer_lines(logs);
  summary += totals.path_lines;
  RunTimes times = run_times(o, totals, logs, records);
  times.lost = totals.lost;
  summary += spread_lines(times);
  if (runs_viz(o.path)) summary += fmt::format("paths: {}\n", path_choice_name(o.path));
  if (o.compare) {
    summary += fmt::format(
        "compare: {} display pictures identical byte for byte on the DVI and vizserver "
        "paths\n",
        totals.compared_displays);
  }
  if (totals.noise_bytes || totals.dropped_readies) {
    summary += fmt::format("faults injected: {} noise bytes, {} READY dropped\n",
                           totals.noise_bytes, totals.dropped_readies);
  }
  for (std::size_t i = 0; i < logs.size(); ++i) {
    summary += fmt::format(
        "back-channel pipeserver {}: {}\n", i,
        logs[i].done.empty() ? "no totals (stopped before its last frame)" : logs[i].done);
  }
  summary += extra;
  summary += fmt::format("report: {}\n", csv_path.string());
  return {csv_text(totals, logs, records, wall.stereo), summary};
}

}  // namespace l2
