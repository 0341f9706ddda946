// The one error type of the displays part: a wall that cannot be shown as asked (no X display,
// too few monitors, an unknown monitor name). Its message is the one line the user reads.
#pragma once

#include <stdexcept>

namespace l2 {

class DisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace l2
