// What the control page (or a script) asked of a run, from the HTTP server's threads to the run's
// own: the run takes the requests in between frames, so every change happens at a frame
// boundary, as a key in the wall window does.
#pragma once

#include <mutex>
#include <string>
#include <vector>

namespace l2 {

enum class ControlAction { Pause, Resume, Save, Stop, Balance, Window };

struct ControlRequest {
  ControlAction action = ControlAction::Pause;
  std::string argument;  // Balance: the mode asked for; Window: "move ID X Y W H", "raise ID"...
};

class ControlInbox {
 public:
  void push(ControlRequest request);
  // Every request since the last call, oldest first.
  std::vector<ControlRequest> take();

 private:
  std::mutex mutex_;
  std::vector<ControlRequest> requests_;
};

}  // namespace l2
