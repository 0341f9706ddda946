// The quad buffer fed eye frames at irregular times, its pixels asserted refresh by refresh: each
// eye frame's picture is a colour of its own, and each refresh's expected eye frame is written
// out by hand (even refreshes the left eye, odd the right). A pair is shown only once both eyes
// are in, from a left-eye refresh; with no new pair the whole pair is shown again; a pair waiting
// for a left-eye refresh survives the next left eye arriving; the displays of the group take a
// pair in the same refresh; a right eye without its left makes no pair.
#include "l2wall/quad_buffer.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace l2 {
namespace {

constexpr int kWidth = 5, kHeight = 3;

std::vector<Display> two_displays() {
  std::vector<Display> displays(2);
  for (int i = 0; i < 2; ++i) {
    displays[static_cast<std::size_t>(i)].id = i;
    displays[static_cast<std::size_t>(i)].width = kWidth;
    displays[static_cast<std::size_t>(i)].height = kHeight;
  }
  return displays;
}

// What reassembly puts on display `d` for eye frame `e`: a colour of its own.
RgbImage eye_picture(int e, int d) {
  return RgbImage(kWidth, kHeight,
                  Rgb{static_cast<std::uint8_t>(10 + e), static_cast<std::uint8_t>(100 + d), 7});
}

// Refresh by refresh: the eye frame each display's front buffer holds (`arrived`, one per
// display) and the eye frame each must show (`want`, -1 black).
struct Step {
  std::vector<int> arrived, want;
};

void run(const std::vector<Step>& steps) {
  const std::vector<Display> displays = two_displays();
  QuadBuffer quad(displays);
  std::vector<RgbImage> front(2);
  const DisplayPictures pictures = [&](int d) -> const RgbImage& {
    return front[static_cast<std::size_t>(d)];
  };
  const RgbImage black(kWidth, kHeight);
  for (std::size_t r = 0; r < steps.size(); ++r) {
    const Step& s = steps[r];
    std::vector<DisplayShown> arrived;
    for (int d = 0; d < 2; ++d) {
      const int e = s.arrived[static_cast<std::size_t>(d)];
      if (e >= 0) front[static_cast<std::size_t>(d)] = eye_picture(e, d);
      arrived.push_back({d, e, 3 + d});
    }
    quad.refresh(r, arrived, pictures);
    for (int d = 0; d < 2; ++d) {
      const int want = s.want[static_cast<std::size_t>(d)];
      EXPECT_TRUE(quad.picture(d) == (want < 0 ? black : eye_picture(want, d)))
          << "refresh " << r << ", display " << d << ": want eye frame " << want;
      EXPECT_EQ(quad.shown()[static_cast<std::size_t>(d)].frame, want) << "refresh " << r;
      EXPECT_EQ(quad.shown()[static_cast<std::size_t>(d)].rank, 3 + d);
    }
  }
}

// Both displays alike: eye frame arrived, eye frame shown.
std::vector<Step> alike(std::initializer_list<std::pair<int, int>> steps) {
  std::vector<Step> out;
  for (const auto& [arrived, want] : steps) out.push_back({{arrived, arrived}, {want, want}});
  return out;
}

TEST(QuadBuffer, EveryRefreshShowsItsEyeOfAWholePair) {
  run(alike({
      {-1, -1},  // 0 L: nothing yet
      {0, -1},   // 1 R: frame 0's left in
      {0, -1},   // 2 L: its right not yet
      {1, -1},   // 3 R: pair 0 whole, but a pair starts at a left-eye refresh only
      {1, 0},    // 4 L: pair 0 front: its left
      {2, 1},    // 5 R: its right; frame 1's left in
      {3, 2},    // 6 L: frame 1's right in now: pair 1 front at once
      {3, 3},    // 7 R
      {3, 2},    // 8 L: no new pair: pair 1 again, left
      {4, 3},    // 9 R: then right; frame 2's left in
      {5, 4},    // 10 L: pair 2
      {5, 5},    // 11 R
      {6, 4},    // 12 L: frame 3's left in, pair 2 again
      {7, 5},    // 13 R: pair 3 whole, waiting for a left-eye refresh
      {8, 6},    // 14 L: frame 4's left in beside it; pair 3 front
      {9, 7},    // 15 R: pair 4 whole
      {9, 8},    // 16 L: pair 4 front
      {9, 9},    // 17 R
  }));
}

TEST(QuadBuffer, TheGroupTakesAPairTogether) {
  run({
      {{0, 0}, {-1, -1}},  // 0 L: both have frame 0's left
      {{1, 0}, {-1, -1}},  // 1 R: display 0's pair whole, display 1's not
      {{1, 0}, {-1, -1}},  // 2 L: display 0 waits for display 1
      {{1, 1}, {-1, -1}},  // 3 R: both whole, a right-eye refresh
      {{1, 1}, {0, 0}},    // 4 L: both take pair 0
      {{1, 1}, {1, 1}},    // 5 R
  });
}

TEST(QuadBuffer, ARightEyeWithoutItsLeftMakesNoPair) {
  run(alike({
      {1, -1},  // 0 L: frame 0's right, its left never seen
      {1, -1},  // 1 R
      {2, -1},  // 2 L: frame 1's left
      {3, -1},  // 3 R: frame 1 whole
      {3, 2},   // 4 L
      {5, 3},   // 5 R: frame 2's right without its left: ignored
      {5, 2},   // 6 L: pair 1 again
      {5, 3},   // 7 R
  }));
}

TEST(QuadBuffer, WaitsWhileAPairIsNotYetShownToBothEyes) {
  const std::vector<Display> displays = two_displays();
  QuadBuffer quad(displays);
  RgbImage left = eye_picture(0, 0), right = eye_picture(1, 0);
  const RgbImage* front = &left;
  const DisplayPictures pictures = [&](int) -> const RgbImage& { return *front; };
  quad.refresh(0, std::vector<DisplayShown>{{0, 0, 0}, {1, 0, 0}}, pictures);
  EXPECT_FALSE(quad.waiting());  // a lone left eye is no pair
  front = &right;
  quad.refresh(1, std::vector<DisplayShown>{{0, 1, 0}, {1, 1, 0}}, pictures);
  EXPECT_TRUE(quad.waiting());  // whole, not shown
  quad.refresh(2, {}, pictures);
  EXPECT_TRUE(quad.waiting());  // its left shown, not its right
  quad.refresh(3, {}, pictures);
  EXPECT_FALSE(quad.waiting());
  // Three pairs of two pictures and a black one, per display.
  EXPECT_EQ(quad.buffer_bytes(), 2u * 7u * static_cast<std::uint64_t>(left.bytes().size()));
}

}  // namespace
}  // namespace l2
