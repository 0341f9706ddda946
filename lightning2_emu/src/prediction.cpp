// Predicted frames (router.hpp): a frame is taken to hold its input's last headers with a new
// frame bit, and every header of it is checked before the frame's routing counts. Here: an
// input's state (router_detail.hpp: what its last parse left, parsed or predicted from), the
// checks that are not made in the copy loop (router_write.cpp makes those), and what happens
// when one fails.
#include <algorithm>

#include "lightning2_emu/router.hpp"
#include "pixel_copy.hpp"
#include "router_detail.hpp"
#include "strip_headers/extension_word.hpp"

namespace l2 {
namespace router_detail {
namespace {

// Headers of the last parse, ahead, whose lines headers_hold() asks for while it reads one.
constexpr int kCheckAhead = 8;

}  // namespace

void InputScan::init(int input, int band_lists) {
  input_ = input;
  layout_.stats.input = input;
  layout_.bands.resize(band_lists);
}

void InputScan::no_signal() {
  frame_ = InputFrame{};
  layout_.stats = InputFrameStats{};
  layout_.stats.input = input_;
  for (auto& band : layout_.bands) band.clear();
  layout_.composited = 0;
  state_ = State::None;
}

// A frame with an error or a tear is not predicted from: the next one is parsed.
void InputScan::parse(const InputFrame& frame, const std::vector<Target>& targets) {
  frame_ = frame;
  parse_frame(frame_, input_, targets, layout_, scratch_);
  const InputFrameStats& st = layout_.stats;
  state_ = st.errors.total() == 0 && st.parities != 3 ? State::Parsed : State::None;
}

bool InputScan::predict(const InputFrame& frame) {
  if (state_ == State::None || frame.width != frame_.width || frame.height != frame_.height ||
      frame.stride != frame_.stride || frame.bytes_per_pixel != frame_.bytes_per_pixel) {
    return false;
  }
  frame_ = frame;
  state_ = State::Predicted;
  parity_ = 0;
  if (layout_.parity_at >= 0) {
    const std::uint8_t* p = frame_.data + layout_.parity_at;
    parity_ = static_cast<int>(
        header_value(p, p + frame_.bytes_per_pixel) >> header_bits::kFrameShift & 1);
    layout_.stats.parities = static_cast<std::uint8_t>(parity_ ? 2 : 1);
  }
  return true;
}

std::uint64_t InputScan::frame_bit() const {
  return predicted() && parity_ ? kMessageFrameBit : 0;
}

bool any_overlap(const std::vector<Run>& runs, const std::vector<Area>& areas) {
  for (const Run& r : runs) {
    for (const Area& a : areas) {
      if (r.dst_y < a.y1 && a.y0 < r.dst_y + r.rows && r.dst_x < a.x1 && a.x0 < r.dst_x + r.length)
        return true;
    }
  }
  return false;
}

bool InputScan::headers_hold(bool runs) const {
  const InputFrame& f = frame_;
  const int bpp = f.bytes_per_pixel;
  const std::uint64_t bit = frame_bit();
  auto holds = [&](std::int64_t at, std::uint64_t message) {
    const std::uint8_t* p = f.data + at;
    const std::uint64_t raw = header_value(p, p + bpp);
    if (message == RememberedHeader::kAnyEnd) {
      const auto h = decode(raw);
      return h && h->op == StripOp::End;
    }
    return raw == predicted_header(message | bit);
  };
  bool ok = true;
  const std::vector<RememberedHeader>& others = layout_.others;
  const std::size_t n = others.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (k + kCheckAhead < n) pixel_copy::prefetch_line(f.data + others[k + kCheckAhead].at);
    ok &= holds(others[k].at, others[k].message);
  }
  if (!runs) return ok;
  for (const auto& band : layout_.bands) {
    for (const Run& r : band) {
      // A KEY or DEPTH strip's header is followed by its extension word, which must repeat too.
      const int gap = r.ext ? kHeaderPixels + kExtensionPixels : kHeaderPixels;
      const std::int64_t first = r.src - std::int64_t{gap} * bpp;
      const RunHeaders headers(r.message | bit);
      for (int k = 0; k < r.rows; ++k) {
        if (k + kCheckAhead < r.rows) {
          pixel_copy::prefetch_line(f.data + first + (k + kCheckAhead) * f.stride);
        }
        const std::uint8_t* p = f.data + first + k * f.stride;
        ok &= header_value(p, p + bpp) == headers.strip(k);
        if (r.ext) {
          const std::uint8_t* w = f.data + first + k * f.stride + kHeaderPixels * bpp;
          ok &= header_value(w, w + bpp) == r.ext;
        }
      }
    }
  }
  return ok;
}

}  // namespace router_detail

using router_detail::BandState;
using router_detail::DisplayBands;

bool Router::predictions_clear_of_earlier(std::span<const std::uint8_t> route_input) const {
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  for (std::size_t task = 0; task < band_tasks_.size(); ++task) {
    const BandState& bs = display_state_[band_tasks_[task].display].bands[band_tasks_[task].band];
    if (bs.areas.empty()) continue;  // nothing earlier in this band
    for (int i = 0; i < inputs; ++i) {
      if (route_input[i] && inputs_[i].predicted() &&
          router_detail::any_overlap(inputs_[i].runs(static_cast<int>(task)), bs.areas)) {
        return false;
      }
    }
  }
  return true;
}

bool Router::confirm_predictions(std::span<const std::uint8_t> route_input, bool copied) {
  confirm_inputs_.clear();
  for (int i = 0; i < static_cast<int>(inputs_.size()); ++i) {
    if (inputs_[i].predicted()) confirm_inputs_.push_back(i);
  }
  if (confirm_inputs_.empty()) return true;
  mispredicted_.assign(inputs_.size(), 0);
  auto routed = [&](int i) { return i < static_cast<int>(route_input.size()) && route_input[i]; };
  // The headers the copy did not check (all of an input it did not copy), in parallel.
  pool_.run(static_cast<int>(confirm_inputs_.size()), [&](int task, int) {
    const int i = confirm_inputs_[task];
    if (!inputs_[i].headers_hold(!(copied && routed(i)))) mispredicted_[i] = 1;
  });
  for (DisplayBands& ds : display_state_) {
    for (BandState& bs : ds.bands) {
      for (const int i : bs.mispredicted) mispredicted_[i] = 1;
      bs.mispredicted.clear();
    }
  }
  predictions_.predicted += confirm_inputs_.size();
  if (!copied) predictions_.checked_first += confirm_inputs_.size();
  reparse_inputs_.clear();
  for (const int i : confirm_inputs_) {
    if (mispredicted_[i]) {
      reparse_inputs_.push_back(i);
    } else {
      inputs_[i].verified();
    }
  }
  if (reparse_inputs_.empty()) return true;
  predictions_.mispredicted += reparse_inputs_.size();
  pool_.run(static_cast<int>(reparse_inputs_.size()),
            [this](int task, int) { inputs_[reparse_inputs_[task]].reparse(targets_); });
  add_planes();  // the parse may find KEY or DEPTH strips the prediction did not have
  return false;
}

}  // namespace l2
