// Limits checked on a wall file's text before TOML parses it. toml++ recurses once per level of
// nested tables (dotted keys, [a.b.c] headers, inline tables), so a small file of deep keys
// overflows the stack of every program that reads walls. A wall needs two or three levels;
// refusing deep nesting and long keys up front keeps a hostile file a one-line error.
#pragma once

#include <string_view>

namespace l2 {

constexpr int kMaxTomlDepth = 16;
constexpr int kMaxTomlKeyLength = 256;

// Throws LayoutError "<file>:<line>: ..." at the first key or bracket beyond a limit. Text that
// is not TOML passes when it breaks no limit: the parser reports it.
void check_toml_shape(std::string_view text, std::string_view file);

}  // namespace l2
