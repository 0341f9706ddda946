// Where a program finds the project's other programs and files by default: relative to where
// it runs from, never a path compiled in. Installed (`cmake --install`), the programs share
// PREFIX/bin and the files are in PREFIX/share/lightning2; in a build tree each program is in
// build/<preset>/<part>/ and the files in the working tree the build folder sits in.
//
// Example:
//
//   const std::string pipeserver = l2::sibling_program("pipeserver").string();
//   const std::filesystem::path bunny = "data/bunny.ply";
//   const std::filesystem::path model =
//       l2::project_files(bunny).value_or(std::filesystem::path()) / bunny;
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

namespace l2 {

// The folder of the running executable (empty if /proc/self/exe cannot be read).
inline std::filesystem::path executable_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}

// The project's program `name`: beside this executable (installed), else in its part's folder
// of the same build tree (build/<preset>/<name>/<name>, this one being in another part's
// folder). Returns the first that exists, else the one beside this executable, so that an
// error names where it was looked for.
inline std::filesystem::path sibling_program(const std::string& name) {
  const std::filesystem::path here = executable_dir();
  const std::filesystem::path beside = here / name;
  const std::filesystem::path built = here.parent_path() / name / name;
  std::error_code ec;
  if (std::filesystem::is_regular_file(beside, ec)) return beside;
  if (std::filesystem::is_regular_file(built, ec)) return built;
  return beside;
}

// The folder the project's files are found in, the one holding `marker` (a relative path such
// as "walls/kd-2x2.toml"): PREFIX/share/lightning2 beside the installed bin/, else the nearest
// folder above this executable (a build tree inside the working tree), else the nearest above
// the current folder. nullopt when none holds it.
inline std::optional<std::filesystem::path> project_files(const std::filesystem::path& marker) {
  std::error_code ec;
  const auto holds = [&](const std::filesystem::path& dir) {
    return !dir.empty() && std::filesystem::exists(dir / marker, ec);
  };
  const std::filesystem::path here = executable_dir();
  if (const auto shared = here.parent_path() / "share" / "lightning2"; holds(shared)) return shared;
  for (std::filesystem::path start : {here, std::filesystem::current_path(ec)}) {
    for (std::filesystem::path dir = start; !dir.empty(); dir = dir.parent_path()) {
      if (holds(dir)) return dir;
      if (dir == dir.parent_path()) break;
    }
  }
  return std::nullopt;
}

}  // namespace l2
