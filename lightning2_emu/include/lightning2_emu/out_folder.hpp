// The --out folder of route and sequence. report.json is written last, and an earlier run's is
// removed before anything is written, so a report.json in OUT belongs to a run that wrote all
// its pictures. When a file cannot be written, the error also says what OUT holds of this run
// (partly_written(), image/folders.hpp).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace l2 {

// Makes OUT (std::runtime_error "--out OUT: ..." when it cannot) and removes its report.json.
void prepare_out(const std::filesystem::path& out);

}  // namespace l2
