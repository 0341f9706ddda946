#include "live_windows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "balance/message_words.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_fault.hpp"
#include "session_desktops.hpp"
#include "waiting_message.hpp"

namespace l2 {

LiveWindows::LiveWindows(const Session& session) {
  for (const SessionWindow& w : session.windows) {
    now_.push_back({w.id, w.on_canvas});
    ids_.push_back(w.id);
    sources_.push_back(w.source);
  }
  for (int k = 0; k < session.shares; ++k) {  // closed until a browser shares a screen
    ids_.push_back(share_window_id(session, k));
    sources_.push_back("share");
  }
  lines_.push_back(encode(WindowsMessage{0, now_}));
}

LiveWindows::Refusal LiveWindows::command(std::string_view line) {
  Words w(line, "command");
  const std::string_view verb = w.word();
  if (verb != "move" && verb != "raise" && verb != "close")
    return {"expected 'move ID X Y W H', 'raise ID' or 'close ID'"};
  try {
    const int id = static_cast<int>(w.integer("ID", 0, kMaxWindowId));
    Rect r;
    if (verb == "move") {
      r.x = static_cast<int>(w.integer("X", -kWindowReach, kWindowReach));
      r.y = static_cast<int>(w.integer("Y", -kWindowReach, kWindowReach));
      r.w = static_cast<int>(w.integer("W", 1, kMaxWindowSide));
      r.h = static_cast<int>(w.integer("H", 1, kMaxWindowSide));
    }
    w.end();
    if (std::string why = apply(verb, id, r); !why.empty()) return {why, true};
    pending_.push_back(verb == "move" ? fmt::format("move {} {} {} {} {}", id, r.x, r.y, r.w, r.h)
                                      : fmt::format("{} {}", verb, id));
  } catch (const ControlError& e) {
    return {e.what()};
  }
  return {};
}

int LiveWindows::open(int id, const Rect& r) {
  now_.erase(std::remove_if(now_.begin(), now_.end(), [id](auto& p) { return p.id == id; }),
             now_.end());
  now_.push_back({id, r});
  if (std::find(ids_.begin(), ids_.end(), id) == ids_.end()) {
    ids_.push_back(id);
    sources_.push_back("share");
  }
  pending_.push_back(fmt::format("open {} {} {} {} {}", id, r.x, r.y, r.w, r.h));
  return static_cast<int>(lines_.size());
}

std::string LiveWindows::apply(std::string_view verb, int id, const Rect& r) {
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
    at->on_canvas = r;
  }
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

void LiveWindows::serve(PipeserverSet& pipeservers, SessionDesktops* desktops) {
  if (desktops) desktops->take_updates();
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
      std::vector<std::string> answer{line_for(m.frame)};
      if (desktops) {
        try {
          const std::vector<std::string> lines =
              desktops->answer(h.pipeserver, m.frame, shown_at(m.frame));
          answer.insert(answer.end(), lines.begin(), lines.end());
        } catch (const DesktopError& e) {
          throw RunFault(fmt::format("pipeserver {}: {}", h.pipeserver, e.what()));
        }
      }
      try {
        for (const std::string& line : answer) h.windows->send_line(line);
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
