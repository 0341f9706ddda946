#include "lightning2_emu/out_folder.hpp"

#include <fmt/format.h>

#include <system_error>

#include "image/folders.hpp"

namespace l2 {

void prepare_out(const std::filesystem::path& out) {
  make_folders(out, "--out");
  const std::filesystem::path report = out / "report.json";
  std::error_code error;
  if (std::filesystem::is_directory(std::filesystem::symlink_status(report, error))) {
    // Refused now, not after every picture is written; and someone's folder is not removed.
    throw std::runtime_error(
        fmt::format("{}: cannot write: a folder, not a file", report.string()));
  }
  if (std::filesystem::remove(report, error); error) {
    throw std::runtime_error(fmt::format("{}: cannot remove the report of an earlier run: {}",
                                         report.string(), error.message()));
  }
}

}  // namespace l2
