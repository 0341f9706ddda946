#include "l2wall/quad_buffer.hpp"

#include <algorithm>
#include <utility>

namespace l2 {
namespace {

// `from` into `to`, the same size: one span, into the buffer allocated once.
void copy_into(const RgbImage& from, RgbImage& to) {
  std::ranges::copy(from.bytes(), to.bytes().begin());
}

}  // namespace

QuadBuffer::QuadBuffer(std::span<const Display> displays) {
  displays_.resize(displays.size());
  for (std::size_t i = 0; i < displays.size(); ++i) {
    Buffers& b = displays_[i];
    const Display& d = displays[i];
    b.id = d.id;
    for (Pair& p : b.pairs)
      for (RgbImage& eye : p.eye) eye = RgbImage(d.width, d.height);
    b.black = RgbImage(d.width, d.height);
    shown_.push_back({d.id, -1, 0});
  }
}

void QuadBuffer::refresh(std::uint64_t refresh, std::span<const DisplayShown> arrived,
                         const DisplayPictures& pictures) {
  refresh_ = refresh;
  for (const DisplayShown& a : arrived) {
    const auto b = std::find_if(displays_.begin(), displays_.end(),
                                [&](const Buffers& x) { return x.id == a.display; });
    if (b == displays_.end()) continue;
    b->rank = a.rank;
    if (a.frame < 0 || a.frame == b->arrived) continue;
    b->arrived = a.frame;
    take(*b, a.frame, pictures(a.display));
  }
  const int eye = static_cast<int>(refresh % 2);
  if (eye == 0) promote();
  for (std::size_t i = 0; i < displays_.size(); ++i) {
    Buffers& b = displays_[i];
    const int frame = b.front < 0 ? -1 : b.pairs[b.front].frame;
    shown_[i] = {b.id, frame < 0 ? -1 : 2 * frame + eye, b.rank};
    if (frame >= 0) b.right_shown = eye == 1;
  }
}

void QuadBuffer::take(Buffers& b, int eye_frame, const RgbImage& picture) {
  const int eye = eye_frame % 2, frame = eye_frame / 2;
  const RgbImage& size = b.black;
  if (picture.width() != size.width() || picture.height() != size.height()) return;  // lost
  if (eye == 0) {
    if (b.filling < 0) b.filling = free_pair(b);
    Pair& p = b.pairs[b.filling];
    p.frame = frame;
    copy_into(picture, p.eye[0]);
    return;
  }
  // A right eye whose left never arrived here makes no pair: the display keeps its front pair.
  if (b.filling < 0 || b.pairs[b.filling].frame != frame) return;
  Pair& p = b.pairs[b.filling];
  copy_into(picture, p.eye[1]);
  if (b.ready >= 0) b.pairs[b.ready].frame = -1;  // a newer pair supersedes one still waiting
  b.ready = std::exchange(b.filling, -1);
}

int QuadBuffer::free_pair(const Buffers& b) {
  for (int i = 0; i < 3; ++i)
    if (i != b.front && i != b.ready) return i;
  return 0;  // not reached: three pairs, at most two in use
}

void QuadBuffer::promote() {
  if (displays_.empty()) return;
  const Buffers& first = displays_.front();
  if (first.ready < 0) return;
  const int frame = first.pairs[first.ready].frame;
  // Swap lock: all displays take the same pair in the same refresh, or none does.
  for (const Buffers& b : displays_)
    if (b.ready < 0 || b.pairs[b.ready].frame != frame) return;
  for (Buffers& b : displays_) {
    if (b.front >= 0) b.pairs[b.front].frame = -1;
    b.front = std::exchange(b.ready, -1);
  }
}

const RgbImage& QuadBuffer::picture(int id) const {
  const auto b = std::find_if(displays_.begin(), displays_.end(),
                              [&](const Buffers& x) { return x.id == id; });
  if (b == displays_.end() || b->front < 0) {
    static const RgbImage none;
    return b == displays_.end() ? none : b->black;
  }
  return b->pairs[b->front].eye[refresh_ % 2];
}

bool QuadBuffer::waiting() const {
  return std::any_of(displays_.begin(), displays_.end(), [](const Buffers& b) {
    return b.ready >= 0 || (b.front >= 0 && !b.right_shown);
  });
}

std::uint64_t QuadBuffer::buffer_bytes() const {
  std::uint64_t bytes = 0;
  for (const Buffers& b : displays_) {
    for (const Pair& p : b.pairs)
      for (const RgbImage& eye : p.eye) bytes += eye.bytes().size();
    bytes += b.black.bytes().size();
  }
  return bytes;
}

}  // namespace l2
