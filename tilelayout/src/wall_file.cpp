#include "tilelayout/wall_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "command_line/printable.hpp"
#include "tilelayout/tile_layout.hpp"
#include "toml_shape.hpp"
#include "wall_sections.hpp"

namespace l2 {

Wall parse_wall(std::string_view toml_text, const std::filesystem::path& path_for_messages) {
  const TomlSource source{path_for_messages.string()};
  check_toml_shape(toml_text, source.file);
  toml::table doc;
  try {
    doc = toml::parse(toml_text, source.file);
  } catch (const toml::parse_error& e) {
    const int line = static_cast<int>(e.source().begin.line);
    // The description quotes the file: escaped, it stays one line and cannot reach a terminal.
    throw LayoutError(
        fmt::format("{}:{}: malformed TOML: {}", source.file, line, printable(e.description())));
  }
  const TomlFields top(doc, "", source,
                       {"name", "canvas", "display_grid", "display", "tiling", "pipeservers",
                        "mesh", "depth", "overlay", "balance"});
  Wall wall;
  wall.source = path_for_messages;
  wall.name = top.string("name").value_or(path_for_messages.stem().string());
  read_displays(top, wall);
  read_canvas(top, wall);
  read_tiling(top, wall);
  read_pipeservers_and_mesh(top, wall);
  read_compositing(top, wall);
  read_balance(top, wall);
  return wall;
}

Wall load_wall(const std::filesystem::path& path) {
  // A directory opens as a stream here and reads as nothing, which would be reported as a wall
  // without displays. (Not "anything but a regular file": a pipe such as <(...) is a fine wall.)
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw LayoutError(fmt::format("{}: cannot read: {}", path.string(), std::strerror(EISDIR)));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw LayoutError(fmt::format("{}: cannot read: {}", path.string(), std::strerror(errno)));
  }
  // Read with a limit: a wall file is a few kilobytes, and /dev/zero or a wrong file (a frame
  // dump, a log) would otherwise be read to the end of memory before TOML refuses it.
  constexpr std::size_t kMaxBytes = 16u << 20;
  std::string text(kMaxBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxBytes) {
    throw LayoutError(
        fmt::format("{}: more than {} MiB: not a wall file", path.string(), kMaxBytes >> 20));
  }
  return parse_wall(text, path);
}

Wall default_wall() {
  return parse_wall(default_wall_toml(), "walls/kd-2x2.toml (built in)");
}

}  // namespace l2
