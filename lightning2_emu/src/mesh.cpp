#include "lightning2_emu/mesh.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "strip_headers/strip_header.hpp"

namespace l2 {

Mesh::Mesh(int rows, int columns, InputLimit limit)
    : rows_(rows), columns_(columns), limit_(limit) {
  if (rows < 1 || rows > kMaxRows) {
    throw MeshError(fmt::format("mesh rows must be 1..{}, got {}", kMaxRows, rows));
  }
  if (columns < 1 || columns > kMaxColumns) {
    throw MeshError(
        fmt::format("mesh columns must be 1..{} (64 displays fit the 6-bit display field), got {}",
                    kMaxColumns, columns));
  }
  if (limit.width < 2 || limit.height < 1 || limit.width > kMaxInputSide ||
      limit.height > kMaxInputSide) {
    throw MeshError(fmt::format("board input limit must be 2x1..{}x{}, got {}x{}", kMaxInputSide,
                                kMaxInputSide, limit.width, limit.height));
  }
}

Mesh Mesh::fit(int inputs, int displays, InputLimit limit) {
  const int rows = std::max(1, (inputs + Board::kInputs - 1) / Board::kInputs);
  const int columns = std::max(1, (displays + Board::kOutputs - 1) / Board::kOutputs);
  if (displays > kMaxDisplays) {
    throw MeshError(fmt::format("{} displays asked for, the mesh addresses at most {}", displays,
                                kMaxDisplays));
  }
  if (rows > kMaxRows) {
    throw MeshError(
        fmt::format("{} inputs asked for, the mesh takes at most {}", inputs, kMaxRows * 4));
  }
  return Mesh(rows, columns, limit);
}

Board Mesh::board(int row, int column) const {
  if (row < 0 || row >= rows_ || column < 0 || column >= columns_) {
    throw MeshError(
        fmt::format("board ({}, {}) is outside the {}x{} mesh", row, column, rows_, columns_));
  }
  return {row, column};
}

void Mesh::check_input(int input, int width, int height, const std::string& what) const {
  if (input < 0 || input >= input_count()) {
    throw MeshError(fmt::format("{}: input {} is beyond the mesh ({} has inputs 0..{})", what,
                                input, describe(), input_count() - 1));
  }
  if (width > limit_.width || height > limit_.height) {
    throw MeshError(fmt::format("{}: input {} is {}x{}, larger than the board limit {}x{}", what,
                                input, width, height, limit_.width, limit_.height));
  }
  if (width < 1 || height < 1) {
    throw MeshError(fmt::format("{}: input {} is empty ({}x{})", what, input, width, height));
  }
}

void Mesh::check_display(int display, int width, int height) const {
  if (display < 0 || display >= display_count()) {
    throw MeshError(fmt::format("display {} is beyond the mesh ({} has displays 0..{})", display,
                                describe(), display_count() - 1));
  }
  // Headers address columns and rows 0..4095: larger displays would have pixels no strip
  // can reach.
  if (width < 1 || height < 1 || width > kMaxCoordinate + 1 || height > kMaxCoordinate + 1) {
    throw MeshError(fmt::format("display {} is {}x{}: each side must be 1..{}", display, width,
                                height, kMaxCoordinate + 1));
  }
}

std::string Mesh::describe() const {
  return fmt::format("{}x{} boards: {} inputs, {} displays, inputs up to {}x{}", rows_, columns_,
                     input_count(), display_count(), limit_.width, limit_.height);
}

}  // namespace l2
