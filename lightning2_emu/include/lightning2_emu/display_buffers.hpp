// An output display of the mesh: the front buffer it shows and the back buffer the router
// writes the next frame into (spec §6: double-buffered, swapped by its swap-lock group).
#pragma once

#include <utility>

#include "image/rgb_image.hpp"

namespace l2 {

struct DisplaySpec {
  int id = 0;  // the display number strip headers carry, 0..63
  int width = 0, height = 0;
  int swap_group = 0;
};

class DisplayBuffers {
 public:
  DisplayBuffers(const DisplaySpec& spec, Rgb background)
      : spec_(spec),
        front_(spec.width, spec.height, background),
        back_(spec.width, spec.height, background) {}

  const DisplaySpec& spec() const { return spec_; }
  int id() const { return spec_.id; }
  const RgbImage& front() const { return front_; }  // what the display shows
  const RgbImage& back() const { return back_; }
  RgbImage& back() { return back_; }
  void swap() { std::swap(front_, back_); }

 private:
  DisplaySpec spec_;
  RgbImage front_, back_;
};

}  // namespace l2
