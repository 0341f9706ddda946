// A failure of the live run that names the process (pipeserver or compositing server) and the
// frame. The run stops on it: it keeps the displays it has, ends every process it started and
// exits non-zero.
#pragma once

#include <stdexcept>

namespace l2 {

class RunFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace l2
