// What /proc says of the processes on this machine, read once per call: a process's state, and
// the processes whose command line holds some text. Read by ChildProcess (is its child
// stopped?) and by the tests that check what a run left running.
//
// Example:
//
//   for (const pid_t p : l2::processes_with_command_line(std::string("\0--link\0", 8)))
//     if (l2::process_state(p) == 'T') std::printf("%d is stopped\n", p);
#pragma once

#include <sys/types.h>

#include <string>
#include <string_view>
#include <vector>

namespace l2 {

// The state letter of process `pid` ('R', 'S', 'D', 'T' stopped, 't' traced, 'Z' zombie, ...),
// or '\0' when there is no such process (it has ended and been reaped).
char process_state(pid_t pid);

// Whether process `pid` still runs: it exists and is no zombie.
bool process_running(pid_t pid);

// The command line of process `pid` as /proc holds it: its arguments, each ended by '\0' (empty
// when there is no such process).
std::string process_command_line(pid_t pid);

// The processes whose command line holds `needle`, this one included when it does. An argument
// is matched whole by putting '\0' around it: "\0--link\0" is the argument "--link" alone.
std::vector<pid_t> processes_with_command_line(std::string_view needle);

}  // namespace l2
