// Quad-buffered active stereo, as a frame-sequential projector does it: the display stage after
// reassembly that makes every refresh of an active stereo wall show the eye of its parity (even
// refreshes the left eye, odd the right: the glasses follow the emitter, one per swap group) of
// one application frame, the same frame on every display.
//
// Reassembly hands each display eye frames (tilelayout/wall.hpp's frame_eye: 2k the left eye of
// application frame k, 2k+1 its right) whenever they complete, which is not in step with the
// refresh parity and may keep an eye frame for several refreshes. This stage copies each eye
// frame as it arrives into a pair buffer; once both eyes of a frame have arrived on every display
// the pair is ready, and at the next left-eye refresh every display takes it as its front pair in
// the same refresh (swap lock). Until a newer pair is ready the front pair is shown again, left
// then right: never a lone eye repeated, never the two eyes of different frames.
//
// Owns, per display, three pair buffers allocated once (the front pair shown, a ready pair
// waiting for a left-eye refresh, a pair filling, which a left eye may start while a ready pair
// waits), a black picture shown before the first pair, and what it shows in the last refresh.
// All displays are one swap group: an active stereo wall has one (wall_stereo.cpp refuses more).
// Pure logic over pictures handed in, so its pixels can be asserted refresh by refresh.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "l2wall/column_records.hpp"
#include "l2wall/run_pictures.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class QuadBuffer {
 public:
  // The wall's displays (id and size); their buffers are allocated here, once.
  explicit QuadBuffer(std::span<const Display> displays);

  // Display refresh `refresh`: `arrived` says which eye frame each display's reassembled front
  // buffer holds now (DisplayShown::frame, -1 none yet), `pictures` gives that front buffer, read
  // only for a display whose eye frame is new since the refresh before. A display absent from
  // `arrived` (its column not answering) takes nothing new.
  void refresh(std::uint64_t refresh, std::span<const DisplayShown> arrived,
               const DisplayPictures& pictures);

  // What each display shows in the last refresh, by display id order: DisplayShown::frame is
  // the eye frame (2k + eye) of the front pair's eye shown, -1 before the first pair.
  std::span<const DisplayShown> shown() const { return shown_; }
  // The picture display `id` shows in the last refresh (black before the first pair).
  const RgbImage& picture(int id) const;
  // Whether a pair has arrived whose two eyes the displays have not yet both shown, or the last
  // refresh showed a left eye: the wall ends on a whole pair.
  bool waiting() const;
  // Bytes of the pair buffers and black pictures, all displays.
  std::uint64_t buffer_bytes() const;

 private:
  struct Pair {
    int frame = -1;   // the application frame; -1: free
    RgbImage eye[2];  // left, right
  };
  struct Buffers {
    int id = 0, rank = 0;
    Pair pairs[3];
    int front = -1, ready = -1, filling = -1;  // indices into pairs; -1: none
    int arrived = -1;                          // the eye frame taken in last
    bool right_shown = false;                  // the last refresh showed the front pair's right eye
    RgbImage black;
  };
  // An eye frame new on display `b`: into the filling pair, which a right eye completes.
  void take(Buffers& b, int eye_frame, const RgbImage& picture);
  // The unused pair index of `b` (neither front nor ready).
  static int free_pair(const Buffers& b);
  // At a left-eye refresh: every display takes its ready pair if all have the same one.
  void promote();

  std::vector<Buffers> displays_;
  std::vector<DisplayShown> shown_;
  std::uint64_t refresh_ = 0;
};

}  // namespace l2
