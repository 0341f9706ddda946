// The session-file parser (TOML, docs/session-file.md) on arbitrary text: a session within its
// limits, or one LayoutError line naming the file; nothing else may come out of it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "tilelayout/session_file.hpp"
#include "tilelayout/tile_layout.hpp"

using l2::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const l2::Session session = l2::parse_session(text, "fuzz.toml");
    require(session.windows.size() <= static_cast<std::size_t>(l2::kMaxWindows),
            "a session that parses has at most kMaxWindows windows");
    for (const l2::SessionWindow& w : session.windows) {
      require(w.on_canvas.w >= 1 && w.on_canvas.w <= l2::kMaxWindowSide, "a window's width");
      require(w.on_canvas.h >= 1 && w.on_canvas.h <= l2::kMaxWindowSide, "a window's height");
      require(w.id >= 0 && w.id <= l2::kMaxWindowId, "a window's id");
      require(w.source == "vnc" || w.password_file.empty(), "a password only for a desktop");
    }
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "a session-file error is one line");
    require(message.rfind("fuzz.toml", 0) == 0, "a session-file error names the file first");
  }
  return 0;
}
