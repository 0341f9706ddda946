// What travels on a liveness connection (mpi_session.hpp) and what a reader makes of it: one
// byte at a time, a pulse every kPulseEvery from each end while the rank lives, so that a rank
// whose host's network is cut (its packets dropped, no connection closed) is found by the
// silence; the word of a good end; a rank's word that it ends by its own error, with its exit
// code (the coordinator then blames it as a pipeserver's exit status is blamed on one machine,
// not as a crash); the coordinator's word that it ends the run on a fault it named (the other
// ranks then end without a line of their own); its word that a stop signal ended the run and its
// report is written (the other ranks then end at once, status 0).
//
// Owns: the bytes, the verdict on what came in, the clock of a peer's silence. The reading and
// writing of sockets is liveness.cpp's two small functions; the threads are the session's.
#pragma once

#include <chrono>
#include <string>
#include <string_view>

namespace l2 {

inline constexpr char kLivenessPulse = 'p';
inline constexpr char kLivenessEnded = 'e';
inline constexpr char kLivenessAborting = 'a';
inline constexpr char kLivenessStopped = 's';
// Followed by the exit code in decimal and ';' ("x3;"): digits are none of the words above.
inline constexpr char kLivenessFailed = 'x';
// Often enough that a default timeout holds many pulses, rarely enough to cost nothing.
inline constexpr std::chrono::milliseconds kPulseEvery{200};

// What came in on a connection since it was last read, the most telling first: it ended well,
// it ends by its own error, the coordinator ends the run on a fault, the coordinator ended a run
// a stop signal cut short, it closed without a word (killed, crashed), it pulsed, nothing came.
enum class Heard { ended, failed, aborting, stopped, closed, pulse, nothing };

// `bytes` read at once from the connection; `closed`: the read found its end (or an error).
Heard heard(std::string_view bytes, bool closed);
// The word of a rank that ends by its own error with exit code `code`.
std::string failed_word(int code);
// The exit code a failed word in `bytes` says; -1 when its digits are not all there.
int failed_code(std::string_view bytes);

// How long a peer has been silent, against the liveness timeout.
class Silence {
 public:
  using Clock = std::chrono::steady_clock;
  Silence(std::chrono::milliseconds timeout, Clock::time_point now)
      : timeout_(timeout), last_(now) {}
  void heard(Clock::time_point now) { last_ = now; }
  bool too_long(Clock::time_point now) const { return now - last_ > timeout_; }

 private:
  std::chrono::milliseconds timeout_;
  Clock::time_point last_;
};

// "no word for 3 s", "no word for 0.5 s": the timeout as a message says it.
std::string no_word_for(std::chrono::milliseconds timeout);

// Reads what is there without waiting, `fd` a socket; `heard` of it. With `exit_code`, a failed
// word's code is put there.
Heard read_liveness(int fd, int* exit_code = nullptr);
// Sends one byte without waiting (a cut link's full buffer drops it: the silence says enough).
void send_liveness(int fd, char byte);
// A word of several bytes (failed_word) in one send, which a pulse sent at once cannot split.
void send_liveness(int fd, std::string_view word);
// The last word on a connection (ended, aborting, stopped, failed), said so that it arrives
// although this process ends at once: what the peer sent is read and dropped first, and the
// word is followed by this end's FIN. A socket closed with unread bytes in it is reset, and a
// reset throws away what this end had not yet put on the wire: the peer would see a close
// without the word, and take the end for a crash.
void send_last_word(int fd, std::string_view word);
void send_last_word(int fd, char byte);

}  // namespace l2
