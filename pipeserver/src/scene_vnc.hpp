// `vnc`: a desktop, 1:1 at the canvas's top-left, whose pixels the run's coordinator sends
// (docs/vnc.md): it holds the desktop of its own tiles only, as the coordinator's DESKTOP and
// RECT lines leave it (live_mode.cpp reads them), and no more. Outside the desktop, black.
// In a session a DesktopScene is the desktop of vnc windows, which draw from it
// (make_desktop_window): it then holds the parts of the desktop those windows show here.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pipeserver/picture_view.hpp"
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
  // The desktop's pixels in `r` (inside a region held), rows of r.w * 3 bytes, written to
  // every region they fall in (a session's regions may overlap). Throws
  // std::invalid_argument for a rectangle in no region.
  void put(const Rect& r, const std::uint8_t* rgb);
  int width() const { return width_; }
  int height() const { return height_; }
  // Columns [x_begin, x_end) of desktop row y, from a region that holds them all; black when
  // none does (the coordinator sends what each tile samples: not reached in a run).
  void read_row(int y, int x_begin, int x_end, std::uint8_t* rgb) const;

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override;
  std::vector<DesktopScene*> desktops() override { return {this}; }

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

// A session's vnc window: `desktop` laid on the window as `fit` says, nearest sampling, as a
// picture window lays its picture (so a picture of the desktop draws the same pixels).
std::unique_ptr<Scene> make_desktop_window(const DesktopScene& desktop, SourceFit fit);

}  // namespace l2::detail
