// The Lightning-2 board mesh of spec §5: R rows of boards share pixel buses (4 inputs a row),
// C columns each drive 8 outputs. It decides which inputs and displays exist and how large an
// input a board accepts; everything the emulator refuses at the door is refused here.
#pragma once

#include <stdexcept>
#include <string>

#include "strip_headers/strip_header.hpp"

namespace l2 {

// A configuration the mesh cannot take: one line naming the input, display or limit.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Board {
  static constexpr int kInputs = 4;   // DVI inputs per board
  static constexpr int kOutputs = 8;  // DVI outputs per board
  int row = 0, column = 0;
  int first_input() const { return row * kInputs; }
  int first_display() const { return column * kOutputs; }
};

// The per-input limit of a board (WireGL: 1280 x 1024).
struct InputLimit {
  int width = 1280, height = 1024;
};

class Mesh {
 public:
  // The strip header's 6-bit display field allows 64 displays, so at most 8 columns.
  static constexpr int kMaxColumns = 8;
  static constexpr int kMaxRows = 64;
  // The largest board input limit per side, as a wall file's board_max_width/height allow.
  static constexpr int kMaxInputSide = kMaxFrameSide;

  // Throws MeshError when rows or columns are out of range or the limit is not 2x1..4096x4096.
  Mesh(int rows, int columns, InputLimit limit = {});

  // The smallest mesh with `inputs` inputs and `displays` outputs (at least one board).
  static Mesh fit(int inputs, int displays, InputLimit limit = {});

  int rows() const { return rows_; }
  int columns() const { return columns_; }
  int input_count() const { return rows_ * Board::kInputs; }
  int display_count() const { return columns_ * Board::kOutputs; }
  InputLimit limit() const { return limit_; }

  // Spec §5: input i enters board row i / 4; display d leaves column d / 8, port d mod 8.
  static int board_row_of_input(int input) { return input / Board::kInputs; }
  static int column_of_display(int display) { return display / Board::kOutputs; }
  static int port_of_display(int display) { return display % Board::kOutputs; }
  Board board(int row, int column) const;

  // Throw MeshError with a clear line; `what` names the source (a file, "input 3").
  void check_input(int input, int width, int height, const std::string& what) const;
  void check_display(int display, int width, int height) const;

  std::string describe() const;  // "2x1 boards: 8 inputs, 8 displays, inputs up to 1280x1024"

 private:
  int rows_, columns_;
  InputLimit limit_;
};

}  // namespace l2
