// `vnc`: a desktop, 1:1 at the canvas's top-left, whose pixels the run's coordinator sends
// (docs/vnc.md): it holds the desktop of its own tiles only, as the coordinator's DESKTOP and
// RECT lines leave it (live_mode.cpp reads them), and no more. Outside the desktop, black.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pipeserver/scene.hpp"

namespace l2::detail {

class DesktopScene : public Scene {
 public:
  explicit DesktopScene(std::string address) : address_(std::move(address)) { lit_ = false; }
  const char* name() const override { return "vnc"; }
  const std::string& address() const { return address_; }

  // From the next frame on: a desktop of width x height, of which `regions` are held; a
  // region held before keeps its pixels, a new one starts black.
  void hold(int width, int height, const std::vector<Rect>& regions);
  // The desktop's pixels in `r` (inside a region held), rows of r.w * 3 bytes. Throws
  // std::invalid_argument for a rectangle in no region.
  void put(const Rect& r, const std::uint8_t* rgb);

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override;

 protected:
  void animate(int /*frame*/) override {}

 private:
  struct Region {
    Rect rect;
    RgbImage pixels;
  };
  std::string address_;
  int width_ = 0, height_ = 0;
  std::vector<Region> regions_;
};

}  // namespace l2::detail
