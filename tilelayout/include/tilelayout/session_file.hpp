// Reading a session file (TOML, format in docs/session-file.md): the windows a wall shows, each
// a source laid on a canvas rectangle, in z-order, over a background colour. One-line errors
// naming file, line and field, as wall files have; limits that refuse a hostile file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tilelayout/geometry.hpp"

namespace l2 {

// Each window is a scene of its own, in every pipeserver and in every GL context it draws with:
// a bound keeps the sources a pipeserver opens (files, decoders, models) few.
inline constexpr int kMaxWindows = 32;
inline constexpr int kMaxWindowId = 9999;
inline constexpr int kMaxWindowSide = 16384;
// How far a window may lie off the canvas's top-left corner (and its side past that).
inline constexpr int kWindowReach = 16384;
// Desktops (vnc windows) a session shows: each is an RFB connection of the run's coordinator
// and a copy of that desktop there; windows of the same address and password share one.
inline constexpr int kMaxSessionDesktops = 4;
// Screens shared from the control page's browsers (`shares`) a session shows at once: each is a
// window and a desktop of the coordinator's, fed by HTTP frames.
inline constexpr int kMaxSessionShares = 4;

struct SessionWindow {
  int id = 0;          // what commands name it by: unique in the session
  std::string source;  // picture, movie, mesh, vnc, strips, hotspot, isosurface, patches, swap
  // picture, movie: the file; mesh: the model (empty: the bunny). Relative to the session file.
  // vnc: the desktop's address as written, HOST:DISPLAY or HOST::PORT.
  std::filesystem::path content;
  Rect on_canvas;
  int z = 0;        // higher in front; at equal z, later in the file in front
  std::string fit;  // picture, movie, vnc: fit, fill, stretch or 1:1; mesh: fit or fill; empty: fit
  // vnc: the file `vncpasswd -f` writes (relative to the session file); empty: no password.
  std::filesystem::path password_file;
};

struct Session {
  std::filesystem::path source;        // the file, for messages
  std::uint32_t background = 0;        // 0xRRGGBB, where no window is
  std::vector<SessionWindow> windows;  // back to front (sort_windows)
  int shares = 0;  // screens the control page may share at once (docs/session-file.md)
};

// The id of share slot `slot` (0 .. shares-1): after every window of the file, so the
// coordinator and the pipeservers name a share's window alike without telling each other.
int share_window_id(const Session& session, int slot);

// Parses session text; relative content paths are taken from `path_for_messages`'s folder.
// Throws LayoutError ("s.toml:12: window[1].width: must be 1..16384, got 0").
Session parse_session(std::string_view toml_text, const std::filesystem::path& path_for_messages);
// Reads and parses a session file. Throws LayoutError, also when the file cannot be read.
Session load_session(const std::filesystem::path& path);

// Back to front: by z, and at equal z in the order they are listed.
void sort_windows(std::vector<SessionWindow>& windows);

}  // namespace l2
