// A private desktop over VNC for the tests of `l2wall run`'s vnc scene and vnc windows
// (live_run_vnc_test.cpp): TigerVNC's Xvnc on a display it picks itself, loopback only, and a
// picture that tells its every pixel's position.
#pragma once

#include "displays/x_client.hpp"
#include "displays/xvfb_server.hpp"
#include "wall_run.hpp"

namespace l2::testing_support {

using ::l2::testing::XClient;
using ::l2::testing::XvfbServer;

inline bool installed(const std::string& program) {
  return run_shell("command -v " + program + " >/dev/null", 10s).status.ok();
}

// A picture in which every pixel tells where it is: R and G the position within 256 pixels,
// B which 256-pixel block.
inline RgbImage position_picture(int w, int h) {
  RgbImage p(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      p.set(x, y,
            {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
             static_cast<std::uint8_t>(16 * (x >> 8) + (y >> 8) + 1)});
  return p;
}

// Xvnc at the default wall's canvas size, listening for RFB on 127.0.0.1 only, port 5900 +
// its display number. `password_file`: VncAuth with that file (vncpasswd -f), else no security.
class Xvnc {
 public:
  explicit Xvnc(const fs::path& password_file = {}) {
    const Wall wall = default_wall();
    width = wall.canvas_width;
    height = wall.canvas_height;
    std::vector<std::string> args{"-geometry",     fmt::format("{}x{}", width, height),
                                  "-depth",        "24",
                                  "-interface",    "127.0.0.1",
                                  "-nolisten",     "tcp",
                                  "-AlwaysShared", "-SecurityTypes"};
    if (password_file.empty()) {
      args.push_back("None");
    } else {
      args.insert(args.end(), {"VncAuth", "-PasswordFile", password_file.string()});
    }
    server = std::make_unique<XvfbServer>("Xvnc", args);
    address = "127.0.0.1" + server->display();
  }
  int width = 0, height = 0;
  std::unique_ptr<XvfbServer> server;
  std::string address;  // 127.0.0.1:N
};

}  // namespace l2::testing_support
