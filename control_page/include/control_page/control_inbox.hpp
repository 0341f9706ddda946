// What the control page (or a script) asked of a run, from the HTTP server's threads to the run's
// own: the run takes the requests in between frames, so every change happens at a frame
// boundary, as a key in the wall window does. The run answers each request with what it decided,
// and the HTTP request waits for that answer, so a script learns a refusal from the status, not
// from the events afterwards.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace l2 {

enum class ControlAction { Pause, Resume, Save, Stop, Balance, Window, Share };

struct ControlRequest {
  ControlAction action = ControlAction::Pause;
  // Balance: the mode asked for; Window: "move ID X Y W H", "raise ID"...; Share: "W H CX CY
  // NAME", a screen of W x H frames to show centred at CX,CY (-1 -1: the canvas's centre).
  std::string argument;
  std::uint64_t ticket = 0;  // given by push: the run decides it by this
};

// What the run did with a request, as its events say it.
struct ControlDecision {
  int status = 200;  // 200: done (or taken from the next frame, as `text` says); 4xx: refused
  std::string text;  // "paused: ...", "window not changed: window 9 is not in the session"
};

class ControlInbox {
 public:
  // Queues `request` for the run; returns the ticket its decision comes back under.
  std::uint64_t push(ControlRequest request);
  // Every request since the last call, oldest first.
  std::vector<ControlRequest> take();
  // The run's decision on a request it took.
  void decide(std::uint64_t ticket, ControlDecision decision);
  // The decision on `ticket`, waiting at most `limit` for it. A request the run has not taken by
  // then is withdrawn, so it changes nothing: 503. One taken but not decided yet: 504 (the
  // events will say what the run did).
  ControlDecision wait(std::uint64_t ticket, std::chrono::milliseconds limit);
  // From now on every request waiting, queued or pushed is answered 409 with `why`: a run that
  // ended takes none.
  void close(std::string why);

 private:
  std::mutex mutex_;
  std::condition_variable decided_;
  std::vector<ControlRequest> requests_;
  std::map<std::uint64_t, std::optional<ControlDecision>> waiting_;
  std::uint64_t next_ticket_ = 1;
  std::string closed_;  // why no request is taken any more; empty: they are
};

}  // namespace l2
