// A folder of its own for a wall file and the files it names (colour tables, warps), removed
// after the test: the wall text is parsed as DIR/w.toml, so names relative to it resolve in the
// folder. The wall-file tests of colour matching and warps derive their fixtures from it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

// A wall of one 4x2 display whose [[display]] entry gets `keys` at line 6 (errors name it).
inline std::string one_display_wall(const std::string& keys) {
  const std::string display = "[[display]]\nwidth = 4\nheight = 2\nx = 0\ny = 0\n";
  return display + keys +
         "\n[tiling]\nkind = \"grid\"\ntile_width = 4\ntile_height = 2\n"
         "[pipeservers]\ncount = 1\nframebuffer_width = 20\nframebuffer_height = 10\n";
}

class WallFolder : public ::testing::Test {
 protected:
  // `kind` names the folder: l2-wall-<kind>-<pid>.
  explicit WallFolder(std::string kind) : kind_(std::move(kind)) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("l2-wall-" + kind_ + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "calibration");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  Wall parse(const std::string& text) { return parse_wall(text, dir_ / "w.toml"); }
  // The one-line error parsing `text` gives, or "no error".
  std::string error_of(const std::string& text) {
    try {
      parse(text);
    } catch (const LayoutError& e) {
      return e.what();
    }
    return "no error";
  }
  std::string wall_file() const { return (dir_ / "w.toml").string(); }
  std::filesystem::path dir_;

 private:
  std::string kind_;
};

}  // namespace l2
