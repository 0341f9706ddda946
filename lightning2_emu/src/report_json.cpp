#include "lightning2_emu/report_json.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "image/folders.hpp"

namespace l2 {
namespace {

using nlohmann::json;

json to_json(const StripErrorCounts& e) {
  return {{"check_errors", e.check_errors},
          {"ext_unsupported", e.ext_unsupported},
          {"zero_width", e.zero_width},
          {"truncations", e.truncations},
          {"missing_display", e.missing_display},
          {"clips", e.clips},
          {"total", e.total()}};
}

json to_json(const InputFrameStats& in) {
  json parities = json::array();
  for (int p = 0; p < 2; ++p) {
    if (in.parities >> p & 1) parities.push_back(p);
  }
  json displays = json::array();
  for (int d = 0; d < 64; ++d) {
    if (in.displays_fed >> d & 1) displays.push_back(d);
  }
  return {{"input", in.input},
          {"present", in.present},
          {"copy_strips", in.copy_strips},
          {"key_strips", in.key_strips},
          {"depth_strips", in.depth_strips},
          {"skip_strips", in.skip_strips},
          {"routed_strips", in.routed_strips},
          {"parities", parities},
          {"displays_fed", displays},
          {"errors", to_json(in.errors)}};
}

json to_json(const DisplayFrameStats& d) {
  return {{"display", d.display},
          {"width", d.width},
          {"height", d.height},
          {"strips", d.strips},
          {"covered_pixels", d.covered_pixels},
          {"coverage", d.coverage()},
          {"overdraw_pixels", d.overdraw_pixels}};
}

json to_json(const RouteReport& r) {
  json inputs = json::array(), displays = json::array();
  for (const auto& i : r.inputs) inputs.push_back(to_json(i));
  for (const auto& d : r.displays) displays.push_back(to_json(d));
  return {{"inputs", inputs}, {"displays", displays}, {"errors", to_json(r.errors())}};
}

json to_json(const Emulator::Tick& t) {
  json kinds = json::array(), completed = json::array();
  for (const FrameKind k : t.kinds) kinds.push_back(to_string(k));
  for (const auto& d : t.completed) completed.push_back(to_json(d));
  StripErrorCounts errors;
  for (const auto& i : t.inputs) errors += i.errors;
  return {{"tick", t.index},
          {"swapped_groups", t.swapped_groups},
          {"ready_inputs", t.ready_inputs},
          {"frames", kinds},
          {"completed_groups", t.completed_groups},
          {"completed_displays", completed},
          {"errors", to_json(errors)}};
}

json to_json(const RunReport& r) {
  json inputs = json::array(), displays = json::array(), groups = json::array();
  for (const auto& i : r.inputs) {
    json frames = json::object();
    for (int k = 0; k < 6; ++k) frames[to_string(static_cast<FrameKind>(k))] = i.frames[k];
    inputs.push_back({{"input", i.input},
                      {"frames", frames},
                      {"copy_strips", i.copy_strips},
                      {"key_strips", i.key_strips},
                      {"depth_strips", i.depth_strips},
                      {"skip_strips", i.skip_strips},
                      {"routed_strips", i.routed_strips},
                      {"errors", to_json(i.errors)}});
  }
  for (const auto& d : r.displays) {
    displays.push_back({{"display", d.display},
                        {"frames", d.frames},
                        {"strips", d.strips},
                        {"covered_pixels", d.covered_pixels},
                        {"overdraw_pixels", d.overdraw_pixels}});
  }
  for (const auto& g : r.groups) {
    groups.push_back({{"group", g.id}, {"displays", g.displays}, {"swaps", g.swaps}});
  }
  return {{"ticks", r.ticks},
          {"frames_torn", r.frames(FrameKind::Torn)},
          {"frames_idle", r.frames(FrameKind::Idle)},
          {"frames_new", r.frames(FrameKind::New)},
          {"frames_repeat", r.frames(FrameKind::Repeat)},
          {"frames_early", r.frames(FrameKind::Early)},
          {"frames_predicted", r.frames_predicted},
          {"predictions_missed", r.predictions_missed},
          {"inputs", inputs},
          {"displays", displays},
          {"groups", groups}};
}

// Pretty-printed. The text is made before the file is opened, so that nothing can fail between
// the two and leave an empty report. Strings that are not UTF-8 (file names are bytes) get
// U+FFFD for each bad byte, where dump() would throw.
void write_json(const std::filesystem::path& path, const json& j) {
  const std::string text = j.dump(2, ' ', false, json::error_handler_t::replace) + '\n';
  if (path.has_parent_path()) make_folders(path.parent_path());
  check_writable(path);  // says why, where std::ofstream does not
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
}

}  // namespace

void write_route_report(const std::filesystem::path& path, const RouteReport& report,
                        const Mesh& mesh, const std::vector<std::string>& input_files) {
  json j = to_json(report);
  j["mesh"] = {{"rows", mesh.rows()},
               {"columns", mesh.columns()},
               {"inputs", mesh.input_count()},
               {"displays", mesh.display_count()},
               {"board_max", fmt::format("{}x{}", mesh.limit().width, mesh.limit().height)}};
  j["input_files"] = input_files;
  write_json(path, j);
}

struct SequenceReport::TickLog {
  json ticks = json::array();
};

SequenceReport::SequenceReport() : ticks_(std::make_unique<TickLog>()) {}
SequenceReport::~SequenceReport() = default;

void SequenceReport::add(const Emulator::Tick& tick) {
  ticks_->ticks.push_back(to_json(tick));
}

void SequenceReport::write(const std::filesystem::path& path, const RunReport& run) const {
  json j = to_json(run);
  j["tick_log"] = ticks_->ticks;
  write_json(path, j);
}

}  // namespace l2
