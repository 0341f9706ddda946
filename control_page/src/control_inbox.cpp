#include "control_page/control_inbox.hpp"

#include <utility>

namespace l2 {

void ControlInbox::push(ControlRequest request) {
  const std::lock_guard lock(mutex_);
  requests_.push_back(std::move(request));
}

std::vector<ControlRequest> ControlInbox::take() {
  const std::lock_guard lock(mutex_);
  return std::exchange(requests_, {});
}

}  // namespace l2
