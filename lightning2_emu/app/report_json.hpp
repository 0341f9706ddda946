// Reports as JSON, for report.json files: the counts of route_report.hpp and emulator.hpp.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/route_report.hpp"

namespace l2 {

nlohmann::json to_json(const StripErrorCounts& errors);
nlohmann::json to_json(const InputFrameStats& input);
nlohmann::json to_json(const DisplayFrameStats& display);
nlohmann::json to_json(const RouteReport& report);
nlohmann::json to_json(const Emulator::Tick& tick);
nlohmann::json to_json(const RunReport& report);

// Writes pretty-printed JSON; throws std::runtime_error naming the file.
void write_json(const std::filesystem::path& path, const nlohmann::json& json);

}  // namespace l2
