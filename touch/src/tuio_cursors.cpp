#include "touch/tuio_cursors.hpp"

#include <algorithm>
#include <cmath>

namespace l2 {
namespace {

constexpr char kCursorAddress[] = "/tuio/2Dcur";
// TUIO 1.1's rule for a frame number lower than the last: late unless far behind (a tracker
// that started again) or -1 (a tracker that does not number its frames).
constexpr std::int64_t kRestartGap = 100;

bool is_id(const OscArg& a) {
  return a.is_int32() && a.integer >= 0;
}

bool in_unit(const OscArg& a) {
  return a.is_real() && std::isfinite(a.real) && a.real >= 0.0 && a.real <= 1.0;
}

bool numeric(const OscArg& a) {
  return a.is_real() || a.is_int32();
}

}  // namespace

std::optional<CursorFrame> TuioCursors::take(const OscMessage& m) {
  if (m.address != kCursorAddress) return std::nullopt;
  std::string_view command;
  if (!m.args.empty() && m.args[0].is_text()) command = m.args[0].text;
  bool kept = true;
  if (command == "alive") {
    kept = take_alive(m);
  } else if (command == "set") {
    kept = take_set(m);
  } else if (command == "fseq") {
    return take_fseq(m);
  } else if (command != "source") {
    kept = false;
  }
  if (!kept) ++dropped_;
  return std::nullopt;
}

bool TuioCursors::take_alive(const OscMessage& m) {
  if (m.args.size() - 1 > static_cast<std::size_t>(kMaxTouchCursors)) return false;
  if (!std::all_of(m.args.begin() + 1, m.args.end(), is_id)) return false;
  std::vector<std::int32_t> ids;
  for (auto a = m.args.begin() + 1; a != m.args.end(); ++a)
    ids.push_back(static_cast<std::int32_t>(a->integer));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  next_alive_ = std::move(ids);
  return true;
}

bool TuioCursors::take_set(const OscMessage& m) {
  // "set", id, x, y and up to three more numbers (X, Y, m).
  if (m.args.size() < 4 || m.args.size() > 7) return false;
  if (!is_id(m.args[1]) || !in_unit(m.args[2]) || !in_unit(m.args[3])) return false;
  if (!std::all_of(m.args.begin() + 4, m.args.end(), numeric)) return false;
  const Cursor c{static_cast<std::int32_t>(m.args[1].integer), m.args[2].real, m.args[3].real};
  const auto same = std::find_if(next_set_.begin(), next_set_.end(),
                                 [&c](const Cursor& s) { return s.id == c.id; });
  if (same != next_set_.end()) {
    *same = c;
  } else if (static_cast<int>(next_set_.size()) < kMaxTouchCursors) {
    next_set_.push_back(c);
  } else {
    return false;
  }
  return true;
}

std::optional<CursorFrame> TuioCursors::take_fseq(const OscMessage& m) {
  if (m.args.size() != 2 || !m.args[1].is_int32()) {
    ++dropped_;
    return std::nullopt;
  }
  const std::int64_t fseq = m.args[1].integer;
  const bool late =
      last_fseq_ && fseq != -1 && fseq <= *last_fseq_ && *last_fseq_ - fseq <= kRestartGap;
  if (late) {
    ++dropped_;
    forget_pending();
    return std::nullopt;
  }
  if (fseq != -1) last_fseq_ = fseq;
  std::vector<Cursor> now = next_cursors();
  committed_ = now;
  forget_pending();
  return CursorFrame{static_cast<std::int32_t>(fseq), std::move(now)};
}

// The fingers down once this frame commits: those alive (this frame's list, or the last frame's
// when it said none), each where its last set put it, by id.
std::vector<Cursor> TuioCursors::next_cursors() const {
  const auto alive = [this](std::int32_t id) {
    if (next_alive_) return std::binary_search(next_alive_->begin(), next_alive_->end(), id);
    return std::any_of(committed_.begin(), committed_.end(),
                       [id](const Cursor& c) { return c.id == id; });
  };
  std::vector<Cursor> now;
  for (const Cursor& c : committed_) {
    if (alive(c.id)) now.push_back(c);
  }
  for (const Cursor& s : next_set_) {
    if (!alive(s.id)) continue;
    const auto at =
        std::find_if(now.begin(), now.end(), [&s](const Cursor& c) { return c.id == s.id; });
    if (at != now.end()) {
      *at = s;
    } else {
      now.push_back(s);
    }
  }
  std::sort(now.begin(), now.end(), [](const Cursor& a, const Cursor& b) { return a.id < b.id; });
  return now;
}

void TuioCursors::forget_pending() {
  next_alive_.reset();
  next_set_.clear();
}

}  // namespace l2
