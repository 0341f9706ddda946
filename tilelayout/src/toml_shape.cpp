#include "toml_shape.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// A scan of TOML that knows only what nests: keys (bare or quoted, dotted), [table] headers,
// inline tables, arrays, and the strings and comments whose brackets do not count. It may count
// a level too many on text the parser would refuse anyway, never one too few.
class ShapeScan {
 public:
  ShapeScan(std::string_view text, std::string_view file) : text_(text), file_(file) {}

  void run() {
    while (pos_ < text_.size()) {
      if (expect_key_) {
        key_position();
      } else {
        value_position();
      }
    }
  }

 private:
  struct Open {
    char bracket;  // '[' (array) or '{' (inline table)
    int depth;     // the level of the container itself
  };

  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw LayoutError(fmt::format("{}:{}: {}: not a wall file", file_, line_, what));
  }

  void check_depth(int depth) const {
    if (depth > kMaxTomlDepth) fail(fmt::format("nested more than {} levels deep", kMaxTomlDepth));
  }

  // Where the elements of the innermost open container, or a key's value, sit.
  int value_depth() const {
    if (!open_.empty() && open_.back().bracket == '[') return open_.back().depth + 1;
    return key_depth_;
  }

  void key_position() {
    const char c = peek();
    if (c == ' ' || c == '\t' || c == '\r') {
      ++pos_;
    } else if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == '#') {
      skip_comment();
    } else if (c == '}' && !open_.empty()) {  // an empty inline table
      open_.pop_back();
      ++pos_;
      expect_key_ = false;
    } else if (c == '[' && open_.empty()) {  // [table] or [[array of tables]]
      const bool array = peek(1) == '[';     // its tables sit one level below the array
      pos_ += array ? 2 : 1;
      table_depth_ = read_key(0) + (array ? 1 : 0);
      check_depth(table_depth_);
      expect_key_ = false;
    } else {
      key_depth_ = read_key(open_.empty() ? table_depth_ : open_.back().depth);
      expect_key_ = false;
    }
  }

  // Reads a possibly dotted key below a table at level `base`; returns the level of its last
  // part. Checked part by part: a key of thousands of parts is refused at the first too many.
  int read_key(int base) {
    const std::size_t start = pos_;
    int depth = base;
    for (;;) {
      skip_blanks();
      const char c = peek();
      if (c == '"' || c == '\'') {
        skip_string();
      } else if (!bare_key_char(c)) {
        break;
      } else {
        while (bare_key_char(peek())) ++pos_;
      }
      check_depth(++depth);
      if (pos_ - start > static_cast<std::size_t>(kMaxTomlKeyLength)) {
        fail(fmt::format("a key longer than {} characters", kMaxTomlKeyLength));
      }
      skip_blanks();
      if (peek() != '.') break;
      ++pos_;
    }
    return depth;
  }

  void value_position() {
    const char c = peek();
    if (c == '"' || c == '\'') {
      skip_string();
      return;
    }
    if (c == '#') {
      skip_comment();
      return;
    }
    ++pos_;
    if (c == '\n') {
      ++line_;
      expect_key_ = open_.empty();
    } else if (c == '[' || c == '{') {
      const int depth = value_depth();
      check_depth(depth + 1);
      open_.push_back({c, depth});
      expect_key_ = c == '{';
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      open_.pop_back();
    } else if (c == ',' && !open_.empty() && open_.back().bracket == '{') {
      expect_key_ = true;
    }
  }

  static bool bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  }

  void skip_blanks() {
    while (peek() == ' ' || peek() == '\t') ++pos_;
  }

  void skip_comment() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  // A basic or literal string, one line or multi-line; escapes only in basic strings.
  void skip_string() {
    const char quote = peek();
    const bool multi = peek(1) == quote && peek(2) == quote;
    pos_ += multi ? 3 : 1;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        if (!multi) return;  // unterminated: the parser says so
        ++line_;
      }
      if (c == '\\' && quote == '"' && peek(1) != '\n') {  // a newline is still counted
        pos_ += 2;
        continue;
      }
      if (c == quote && (!multi || (peek(1) == quote && peek(2) == quote))) {
        pos_ += multi ? 3 : 1;
        return;
      }
      ++pos_;
    }
  }

  std::string_view text_;
  std::string_view file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool expect_key_ = true;
  int table_depth_ = 0;  // of the last [table] header
  int key_depth_ = 0;    // of the last key
  std::vector<Open> open_;
};

}  // namespace

void check_toml_shape(std::string_view text, std::string_view file) {
  ShapeScan(text, file).run();
}

}  // namespace l2
