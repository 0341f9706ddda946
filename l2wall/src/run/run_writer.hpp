#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "run_core.hpp"

namespace l2 {

// What a live run writes into OUT: the kept frames' displays (--keep, a save from the control
// page or a key), the displays as they were after a fault (OUT/fault/), and the report
// (report.csv, summary.txt and the files the run's parts add), also after a fault. A file that
// cannot be written ends the run saying what OUT holds and what not. It may not advance frames,
// steer the run or end processes; it reads where the frames are and notes the time it spent
// writing pictures (not the pipeservers').
class RunWriter {
 public:
  RunWriter(RunCore& core, const RunWatch& watch) : core_(core), watch_(watch) {}

  // The displays of `frame` on every path into OUT/frame-<frame>/.
  void save_frame(int frame);
  // After a fault: what the displays show now goes to OUT/fault/. Nullopt if there was nothing;
  // else what is not there (displays lost with a rank of an MPI run), or empty.
  std::optional<std::string> save_displays_after_fault();
  // report.csv and summary.txt after `files` (each a name in OUT and its text); the summary
  // printed and returned. `extra`: the parts' lines for the summary. `fault`: the fault that
  // ended the run at the frames shown, or empty.
  std::string write_report(const std::string& fault, const std::string& extra,
                           std::vector<std::pair<std::string, std::string>> files);

 private:
  void write_report_files(const std::vector<std::pair<std::string, std::string>>& files) const;

  RunCore& core_;
  const RunWatch& watch_;
  int kept_ = 0;  // frames whose pictures were all written (--keep)
};

}  // namespace l2
