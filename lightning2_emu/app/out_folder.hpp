// The --out folder of route and sequence. report.json is written last, and an earlier run's is
// removed before anything is written, so a report.json in OUT belongs to a run that wrote all
// its pictures. When a file cannot be written, the error also says what OUT holds of this run.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace l2 {

// Makes OUT (std::runtime_error "--out OUT: ..." when it cannot) and removes its report.json.
void prepare_out(const std::filesystem::path& out);

// `error` (a file that could not be written, named) with what OUT holds of this run after it:
// "<error>; OUT holds only part of this run: <written>, no report.json", or, with `written`
// empty (nothing of this run written yet), the error alone.
std::runtime_error partly_written(const std::runtime_error& error, const std::filesystem::path& out,
                                  const std::string& written);

}  // namespace l2
