#include "control_page/control_inbox.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace l2 {

std::uint64_t ControlInbox::push(ControlRequest request) {
  const std::lock_guard lock(mutex_);
  request.ticket = next_ticket_++;
  if (!closed_.empty()) {
    waiting_[request.ticket] = ControlDecision{409, closed_};
    return request.ticket;
  }
  waiting_[request.ticket] = std::nullopt;
  requests_.push_back(std::move(request));
  return requests_.back().ticket;
}

std::vector<ControlRequest> ControlInbox::take() {
  const std::lock_guard lock(mutex_);
  return std::exchange(requests_, {});
}

void ControlInbox::decide(std::uint64_t ticket, ControlDecision decision) {
  const std::lock_guard lock(mutex_);
  // Nobody waits any more for a request whose wait ran out: its decision is in the events only.
  const auto at = waiting_.find(ticket);
  if (at == waiting_.end()) return;
  at->second = std::move(decision);
  decided_.notify_all();
}

ControlDecision ControlInbox::wait(std::uint64_t ticket, std::chrono::milliseconds limit) {
  std::unique_lock lock(mutex_);
  const auto at = waiting_.find(ticket);
  if (at == waiting_.end()) return {500, "no such request"};
  decided_.wait_for(lock, limit, [&] { return at->second.has_value(); });
  std::optional<ControlDecision> decision = std::move(at->second);
  waiting_.erase(at);
  if (decision) return *decision;
  const auto queued =
      std::find_if(requests_.begin(), requests_.end(),
                   [ticket](const ControlRequest& r) { return r.ticket == ticket; });
  const double seconds = std::chrono::duration<double>(limit).count();
  if (queued == requests_.end())
    return {504, fmt::format("the run took the request but did not say within {:g} s what it did; "
                             "its events will",
                             seconds)};
  requests_.erase(queued);
  return {503, fmt::format("the run took no request within {:g} s (it is starting, or held up); "
                           "nothing changed, ask again",
                           seconds)};
}

void ControlInbox::close(std::string why) {
  const std::lock_guard lock(mutex_);
  closed_ = std::move(why);
  for (const ControlRequest& r : requests_) waiting_[r.ticket] = ControlDecision{409, closed_};
  requests_.clear();
  for (auto& [ticket, decision] : waiting_)
    if (!decision) decision = ControlDecision{409, closed_};
  decided_.notify_all();
}

}  // namespace l2
