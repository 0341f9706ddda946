#include "tilelayout/session_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// Line numbers matter: errors below name them.
const std::string kSessionWindow =
    "[[window]]\n"            // 1
    "source = \"picture\"\n"  // 2
    "content = \"a.png\"\n"   // 3
    "x = -10\n"               // 4
    "y = 20\n"                // 5
    "width = 300\n"           // 6
    "height = 200\n";         // 7

std::string session_error(const std::string& text) {
  try {
    parse_session(text, "s/x.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SessionFile, WindowsAreReadInZOrderWithTheirFilesBesideTheSession) {
  const Session s = parse_session("background = 0x102030\n" + kSessionWindow + "z = 2\n" +
                                      kSessionWindow + "id = 7\nfit = \"1:1\"\n" +
                                      "[[window]]\nsource = \"mesh\"\nx = 0\ny = 0\nwidth = 1\n"
                                      "height = 1\nfit = \"fill\"\n",
                                  "s/x.toml");
  EXPECT_EQ(s.background, 0x102030u);
  ASSERT_EQ(s.windows.size(), 3u);
  // z 0 (the second, then the third, as listed), then z 2.
  EXPECT_EQ(s.windows[0].id, 7);
  EXPECT_EQ(s.windows[0].fit, "1:1");
  EXPECT_EQ(s.windows[0].content, std::filesystem::path("s/a.png"));
  EXPECT_EQ(s.windows[0].on_canvas, (Rect{-10, 20, 300, 200}));
  EXPECT_EQ(s.windows[1].source, "mesh");
  EXPECT_EQ(s.windows[1].content, std::filesystem::path());
  EXPECT_EQ(s.windows[2].id, 0);
  EXPECT_EQ(s.windows[2].fit, "fit");
}

TEST(SessionFile, AWrongFieldIsOneLineNamingFileLineAndField) {
  EXPECT_EQ(session_error(kSessionWindow + "fit = \"zoom\"\n"),
            "s/x.toml:8: window[0].fit: must be one of fit, fill, stretch, 1:1, got \"zoom\"");
  EXPECT_EQ(session_error("[[window]]\nsource = \"strips\"\nx = 0\ny = 0\nwidth = 1\nheight = 1\n"
                          "fit = \"fit\"\n"),
            "s/x.toml:7: window[0].fit: a strips window frames itself: it takes no fit");
  EXPECT_EQ(session_error("[[window]]\nsource = \"movie\"\nx = 0\ny = 0\nwidth = 1\nheight = 1\n"),
            "s/x.toml:1: window[0].content: missing (a movie window needs its file)");
  EXPECT_EQ(session_error("[[window]]\nsource = \"web\"\n"),
            "s/x.toml:2: window[0].source: must be one of picture, movie, mesh, vnc, strips, "
            "hotspot, isosurface, patches, swap, got \"web\"");
  EXPECT_EQ(session_error(kSessionWindow + "colour = 1\n"),
            "s/x.toml:8: window[0].colour: unknown key (valid here: id, source, content, "
            "password_file, x, y, width, height, z, fit)");
  EXPECT_EQ(session_error(kSessionWindow + "id = 1\n" + kSessionWindow),
            "s/x.toml:9: window[1].id: 1 is already the id of window[0]");
  EXPECT_EQ(session_error("background = 0x1000000\n" + kSessionWindow),
            "s/x.toml:1: background: must be 0..16777215, got 16777216");
  EXPECT_EQ(session_error("background = 1\n"),
            "s/x.toml: window: the session has no windows ([[window]])");
  EXPECT_EQ(session_error("[[window]\n").rfind("s/x.toml:1: malformed TOML: ", 0), 0u);
}

// Room for screens shared from the control page: their windows' ids follow the file's.
TEST(SessionFile, SharesTakeTheIdsAfterTheFilesWindows) {
  const Session s = parse_session("shares = 2\n" + kSessionWindow + "id = 7\n", "s/x.toml");
  EXPECT_EQ(s.shares, 2);
  EXPECT_EQ(share_window_id(s, 0), 8);
  EXPECT_EQ(share_window_id(s, 1), 9);
  EXPECT_EQ(parse_session(kSessionWindow, "s/x.toml").shares, 0);
  EXPECT_EQ(session_error("shares = 5\n" + kSessionWindow),
            "s/x.toml:1: shares: must be 0..4, got 5");
  EXPECT_EQ(session_error("shares = 1\n" + kSessionWindow + "id = 9999\n"),
            "s/x.toml:1: shares: the shares' windows take the ids after the largest (9999), past "
            "9999");
}

// A desktop window: its content is an address, taken as written; its password file is beside
// the session, as its pictures are.
const std::string kDesktopWindow =
    "[[window]]\n"                              // 1
    "source = \"vnc\"\n"                        // 2
    "content = \"127.0.0.1:3\"\n"               // 3
    "x = 0\ny = 0\nwidth = 64\nheight = 48\n";  // 4..7

TEST(SessionFile, AVncWindowShowsADesktopByItsAddress) {
  const Session s = parse_session(
      kDesktopWindow + "fit = \"stretch\"\npassword_file = \"pw\"\n" + kDesktopWindow, "s/x.toml");
  ASSERT_EQ(s.windows.size(), 2u);
  EXPECT_EQ(s.windows[0].source, "vnc");
  EXPECT_EQ(s.windows[0].content, std::filesystem::path("127.0.0.1:3"));
  EXPECT_EQ(s.windows[0].password_file, std::filesystem::path("s/pw"));
  EXPECT_EQ(s.windows[0].fit, "stretch");
  EXPECT_EQ(s.windows[1].password_file, std::filesystem::path());
  EXPECT_EQ(s.windows[1].fit, "fit");
  EXPECT_EQ(session_error("[[window]]\nsource = \"vnc\"\nx = 0\ny = 0\nwidth = 1\nheight = 1\n"),
            "s/x.toml:1: window[0].content: missing (a vnc window needs its desktop, "
            "HOST:DISPLAY)");
  EXPECT_EQ(session_error(kSessionWindow + "password_file = \"pw\"\n"),
            "s/x.toml:8: window[0].password_file: a picture window takes no password");
}

TEST(SessionFile, HostileSizesAndCountsAreRefused) {
  // Five desktops: each is a connection of the coordinator. The same desktop again is none.
  std::string desktops = kDesktopWindow + kDesktopWindow;
  for (int d = 4; d <= 8; ++d)
    desktops += "[[window]]\nsource = \"vnc\"\ncontent = \"h:" + std::to_string(d) +
                "\"\nx = 0\ny = 0\nwidth = 1\nheight = 1\n";
  EXPECT_EQ(session_error(desktops),
            "s/x.toml:36: window[5].content: a 5th desktop, more than a session may show (4)");
  EXPECT_EQ(session_error(kSessionWindow + "z = 1\n" + "[[window]]\nx = 99999\n"),
            "s/x.toml:9: window[1].source: missing (required)");
  std::string many;
  for (int i = 0; i <= kMaxWindows; ++i)
    many += kSessionWindow + "id = " + std::to_string(i) + "\n";
  EXPECT_EQ(session_error(many),
            "s/x.toml:257: window: 33 windows, more than a session may have (32)");
  std::string text = kSessionWindow;
  text.replace(text.find("width = 300"), 11, "width = 16385");
  EXPECT_EQ(session_error(text), "s/x.toml:6: window[0].width: must be 1..16384, got 16385");
  text = kSessionWindow;
  text.replace(text.find("x = -10"), 7, "x = -16385");
  EXPECT_EQ(session_error(text), "s/x.toml:4: window[0].x: must be -16384..16384, got -16385");
  EXPECT_EQ(session_error(std::string(40, '[')).rfind("s/x.toml:1: ", 0), 0u);  // nesting too deep
}

}  // namespace
}  // namespace l2
