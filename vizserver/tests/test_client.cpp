// A pipeserver stand-in as a real process, for tests that need one to die (SIGKILL) or to run
// beside others. Usage:
//   vizserver_test_client PORT PIPESERVER_ID DISPLAYS FRAME [--hang] TILE...
// TILE = d,x,y,w,h,RRGGBB: a solid tile. Sends the tiles of FRAME, then either prints "sent"
// and sleeps until killed (--hang), or sends FRAME_DONE, waits for SWAPPED and prints
// "swapped FRAME". Errors go to stderr with exit status 1.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "viz_link/tile_sender.hpp"

int main(int argc, char** argv) {
  if (argc < 5) {
    fmt::print(stderr, "usage: {} PORT PIPESERVER_ID DISPLAYS FRAME [--hang] TILE...\n", argv[0]);
    return 2;
  }
  try {
    const auto port = static_cast<std::uint16_t>(std::atoi(argv[1]));
    const int id = std::atoi(argv[2]);
    const int displays = std::atoi(argv[3]);
    const auto frame = static_cast<std::uint32_t>(std::atoi(argv[4]));
    bool hang = false;
    auto sender = l2::viz::TileSender::connect("127.0.0.1", port, id, displays);
    std::uint32_t sent = 0;
    for (int i = 5; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--hang") {
        hang = true;
        continue;
      }
      l2::viz::TileTarget t;
      unsigned colour = 0;
      if (std::sscanf(arg.c_str(), "%d,%d,%d,%d,%d,%x", &t.display, &t.x, &t.y, &t.w, &t.h,
                      &colour) != 6) {
        fmt::print(stderr, "bad tile '{}'\n", arg);
        return 2;
      }
      std::vector<std::uint8_t> rgb(static_cast<std::size_t>(t.w) * t.h * 3);
      for (std::size_t p = 0; p < rgb.size(); p += 3) {
        rgb[p] = static_cast<std::uint8_t>(colour >> 16);
        rgb[p + 1] = static_cast<std::uint8_t>(colour >> 8);
        rgb[p + 2] = static_cast<std::uint8_t>(colour);
      }
      sender.send_tile(frame, t, rgb.data(), static_cast<std::size_t>(t.w) * 3);
      ++sent;
    }
    if (hang) {
      fmt::print("sent\n");
      std::fflush(stdout);
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    sender.finish_frame(frame, sent);
    sender.wait_swapped(frame, std::chrono::seconds(10));
    fmt::print("swapped {}\n", frame);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "vizserver_test_client: {}\n", e.what());
    return 1;
  }
}
