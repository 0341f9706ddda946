#include "live_windows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <stdexcept>

#include "l2wall/run_fault.hpp"
#include "waiting_message.hpp"

namespace l2 {

namespace {

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  while (!line.empty()) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string_view::npos) break;
    line.remove_prefix(start);
    const std::size_t n = std::min(line.find(' '), line.size());
    words.push_back(line.substr(0, n));
    line.remove_prefix(n);
  }
  return words;
}

// An integer word in [min, max], or why not.
std::string number(std::string_view word, const char* what, int min, int max, int& out) {
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
  if (ec != std::errc() || end != word.data() + word.size() || out < min || out > max)
    return fmt::format("{} must be {}..{}, got '{}'", what, min, max, word.substr(0, 20));
  return {};
}

}  // namespace

LiveWindows::LiveWindows(const Session& session) {
  for (const SessionWindow& w : session.windows) {
    now_.push_back({w.id, w.on_canvas});
    ids_.push_back(w.id);
    sources_.push_back(w.source);
  }
  lines_.push_back(encode(WindowsMessage{0, now_}));
}

std::string LiveWindows::command(std::string_view line) {
  const std::vector<std::string_view> w = words_of(line);
  const std::string_view verb = w.empty() ? std::string_view() : w[0];
  const std::size_t want = verb == "move" ? 6 : 2;
  if ((verb != "move" && verb != "raise" && verb != "close") || w.size() != want)
    return "expected 'move ID X Y W H', 'raise ID' or 'close ID'";
  int id = 0;
  if (std::string why = number(w[1], "ID", 0, kMaxWindowId, id); !why.empty()) return why;
  const auto at = std::find_if(now_.begin(), now_.end(), [id](auto& p) { return p.id == id; });
  if (at == now_.end()) {
    const bool closed = std::find(ids_.begin(), ids_.end(), id) != ids_.end();
    return fmt::format("window {} {}", id, closed ? "is closed" : "is not in the session");
  }
  if (verb == "close") {
    now_.erase(at);
  } else if (verb == "raise") {
    std::rotate(at, at + 1, now_.end());
  } else {
    Rect r;
    for (const auto& [word, what, min, max, out] :
         {std::tuple{w[2], "X", -kWindowReach, kWindowReach, &r.x},
          std::tuple{w[3], "Y", -kWindowReach, kWindowReach, &r.y},
          std::tuple{w[4], "W", 1, kMaxWindowSide, &r.w},
          std::tuple{w[5], "H", 1, kMaxWindowSide, &r.h}}) {
      if (std::string why = number(word, what, min, max, *out); !why.empty()) return why;
    }
    at->on_canvas = r;
  }
  std::string said;
  for (std::size_t i = 0; i < w.size(); ++i) said += (i ? " " : "") + std::string(w[i]);
  pending_.push_back(said);
  return {};
}

const std::string& LiveWindows::line_for(int frame) {
  while (static_cast<int>(lines_.size()) <= frame) {
    const int next = static_cast<int>(lines_.size());
    for (const std::string& c : pending_)
      changes_.push_back(fmt::format("{} from frame {}", c, next));
    pending_.clear();
    lines_.push_back(encode(WindowsMessage{next, now_}));
  }
  return lines_[static_cast<std::size_t>(frame)];
}

void LiveWindows::serve(PipeserverSet& pipeservers) {
  for (LivePipeserver& h : pipeservers.serving()) {
    if (!h.windows) continue;
    for (;;) {
      const std::optional<WantMessage> want = waiting_message(
          *h.windows, h.pipeserver, [](const std::string& line) { return decode_want(line); });
      if (!want) break;
      const WantMessage& m = *want;
      // A pipeserver asks for each frame once, in order: never more than one ahead of the rest.
      if (m.pipeserver != h.pipeserver || m.frame > static_cast<int>(lines_.size()))
        throw RunFault(fmt::format("pipeserver {}: WANT {} of pipeserver {} out of turn",
                                   h.pipeserver, m.frame, m.pipeserver));
      try {
        h.windows->send_line(line_for(m.frame));
      } catch (const ControlError&) {
        break;
      }
    }
  }
}

std::vector<WindowPlace> LiveWindows::shown_at(int frame) const {
  const int decided = static_cast<int>(lines_.size()) - 1;
  return decode_windows(lines_[static_cast<std::size_t>(std::clamp(frame, 0, decided))]).windows;
}

const std::string& LiveWindows::source_of(int id) const {
  const auto at = std::find(ids_.begin(), ids_.end(), id);
  static const std::string none;
  return at == ids_.end() ? none : sources_[static_cast<std::size_t>(at - ids_.begin())];
}

std::string LiveWindows::summary() const {
  std::string out;
  for (const std::string& c : changes_) out += fmt::format("windows: {}\n", c);
  return out;
}

std::string LiveWindows::windows() const {
  std::string text;
  for (const std::string& line : lines_) text += line + '\n';
  return text;
}

}  // namespace l2
