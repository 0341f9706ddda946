#include "run_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>

#include "image/folders.hpp"
#include "l2wall/run_fault.hpp"
#include "l2wall/run_pictures.hpp"

namespace l2 {

void RunWriter::save_frame(int frame) {
  const Timed timed(core_.frames.writing_ms);
  const std::string& out = core_.options.out;
  const auto dir = std::filesystem::path(out) / fmt::format("frame-{}", frame);
  // A picture that cannot be written stops the run: the error also says what OUT holds, the
  // pictures of this frame written before it included (each is whole or not there).
  const auto write = [&](const DisplayPictures& pictures, const std::string& suffix) {
    try {
      write_display_pictures(dir, core_.wall, pictures, suffix);
    } catch (const RunFault&) {
      throw;
    } catch (const std::runtime_error& e) {
      std::vector<std::string> held;
      if (kept_ > 0) held.push_back(fmt::format("the frames kept before frame {}", frame));
      if (const std::string part = pictures_in(dir); !part.empty())
        held.push_back(fmt::format("{} of frame {}", part, frame));
      throw partly_written(e, out, fmt::format("{}", fmt::join(held, ", ")),
                           "no summary.txt or report.csv of this run");
    }
  };
  for (std::size_t i = 0; i < core_.paths.size(); ++i)
    write(core_.paths[i]->frame_pictures(frame, watch_), core_.picture_suffix(i));
  // Beside the pictures: what the paths know of the displays at this refresh.
  for (const auto& p : core_.paths) {
    for (const auto& [name, text] : p->frame_files()) {
      try {
        write_whole_file(dir / name, text);
      } catch (const std::runtime_error& e) {
        throw partly_written(e, out, fmt::format("the pictures of frame {}", frame),
                             "no summary.txt or report.csv of this run");
      }
    }
  }
  ++kept_;
}

std::optional<std::string> RunWriter::save_displays_after_fault() {
  try {
    const auto dir = std::filesystem::path(core_.options.out) / "fault";
    std::optional<std::string> saved;
    for (std::size_t i = 0; i < core_.paths.size(); ++i) {
      if (const auto pictures = core_.paths[i]->shown()) {
        const auto missing =
            write_display_pictures(dir, core_.wall, *pictures, core_.picture_suffix(i));
        saved = missing.empty() ? ""
                                : fmt::format(" (not display {}: lost with its rank)",
                                              fmt::join(missing, ", "));
      }
    }
    return saved;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "l2wall: could not save the displays: %s\n", e.what());
    return std::nullopt;
  }
}

std::string RunWriter::write_report(const std::string& fault, const std::string& extra,
                                    std::vector<std::pair<std::string, std::string>> files) {
  FrameLedger& f = core_.frames;
  f.totals.pace.clear();  // asked anew: a fault's report may follow a report that failed
  f.totals.path_lines.clear();
  f.totals.path_files.clear();
  for (const auto& p : core_.paths) p->add_totals(f.totals);
  for (auto& file : f.totals.path_files) files.push_back(std::move(file));
  f.totals.lost.clear();
  std::vector<std::string> pipeserver_logs;
  for (const LivePipeserver& h : core_.pipeservers.all()) {
    f.totals.lost.push_back(h.lost);
    pipeserver_logs.push_back(h.report_path);
  }
  const RunReportTexts report =
      run_report(core_.options, core_.wall, pipeserver_logs, f.records, f.totals, extra, fault);
  files.emplace_back("report.csv", report.csv);
  files.emplace_back("summary.txt", report.summary);
  write_report_files(files);
  if (core_.options.progress && fault.empty()) std::fputs("\n", stderr);  // a fault's line ended it
  std::fputs(report.summary.c_str(), stdout);
  return report.summary;
}

// In order; one that cannot be written ends the run, saying what OUT holds and what not.
void RunWriter::write_report_files(
    const std::vector<std::pair<std::string, std::string>>& files) const {
  std::vector<std::string> held;
  if (kept_ > 0) held.emplace_back("the frames kept");
  for (std::size_t i = 0; i < files.size(); ++i) {
    try {
      write_whole_file(std::filesystem::path(core_.options.out) / files[i].first, files[i].second);
    } catch (const std::runtime_error& e) {
      std::vector<std::string> missing;
      for (std::size_t j = i; j < files.size(); ++j) missing.push_back(files[j].first);
      throw partly_written(e, core_.options.out, fmt::format("{}", fmt::join(held, ", ")),
                           fmt::format("no {} of this run", fmt::join(missing, " or ")));
    }
    held.push_back(files[i].first);
  }
}

}  // namespace l2
