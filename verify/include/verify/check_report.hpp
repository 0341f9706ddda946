// A RoutingCheck as text for people: one summary line per display, a line per input whose
// strips were refused, the misplaced runs (the first `max_runs` and a count of the rest) and a
// verdict. What `lightning2_emu route --verify` and `tilelayout --verify` print.
#pragma once

#include <string>
#include <vector>

#include "verify/routing_check.hpp"

namespace l2 {

// "display 1 (640x480) wrong: 307200 planned pixels: 245760 right, 61440 missing, 0 misplaced;
// 0 written twice, 0 behind mullions"
std::string display_summary(const DisplayCheck& display);

// "input 1 rows 0-99 from column 132 (header 408000000403 COPY f=0 d=1 x=0 y=0 w=128):
// 128x100 pixels landed on display 1 at 0,0, belong on display 0 at 512,0"
std::string describe_run(const MisplacedRun& run);

// Every line, without newlines: displays, inputs, runs, verdict last.
std::vector<std::string> check_report(const RoutingCheck& check, int max_runs = 20);

}  // namespace l2
