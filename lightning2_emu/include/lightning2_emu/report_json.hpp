// report.json of the route and sequence commands: the counts of route_report.hpp and
// emulator.hpp as JSON. The JSON library stays inside report_json.cpp: it is heavy to compile,
// and only this file needs it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/mesh.hpp"
#include "lightning2_emu/route_report.hpp"

namespace l2 {

// `route`: the frame's counts, the mesh and the input files (a byte of a name that is not UTF-8
// is written as U+FFFD). Throws std::runtime_error naming the file when it cannot be written.
void write_route_report(const std::filesystem::path& path, const RouteReport& report,
                        const Mesh& mesh, const std::vector<std::string>& input_files);

// `sequence`: what every refresh did, collected as the run goes, then the run's counts.
class SequenceReport {
 public:
  SequenceReport();
  ~SequenceReport();
  void add(const Emulator::Tick& tick);
  // Throws std::runtime_error naming the file when it cannot be written.
  void write(const std::filesystem::path& path, const RunReport& run) const;

 private:
  struct TickLog;
  std::unique_ptr<TickLog> ticks_;
};

}  // namespace l2
