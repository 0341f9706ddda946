// Writing TOML: the one way the project quotes a string into a file it writes (an imported wall,
// a golden manifest), so what it writes always reads back as the same string.
#pragma once

#include <string>
#include <string_view>

namespace l2 {

// A TOML basic string on one line: quotes and backslashes escaped, and control characters too
// (\n, \t, \uXXXX), which TOML forbids raw in a string and which would let a name break the file.
// UTF-8 is kept as it is.
std::string toml_quoted(std::string_view text);

}  // namespace l2
