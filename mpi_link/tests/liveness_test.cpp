// What a liveness connection's reader makes of its bytes, and the clock of a peer's silence.
#include "mpi_link/liveness.hpp"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "base/fd.hpp"
#include "base/socket.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

TEST(Liveness, TheMostTellingWordWins) {
  EXPECT_EQ(heard("ppp", false), Heard::pulse);
  EXPECT_EQ(heard("", false), Heard::nothing);
  EXPECT_EQ(heard("", true), Heard::closed);
  EXPECT_EQ(heard("ppe", true), Heard::ended);  // its word, then its close: a good end
  EXPECT_EQ(heard("pa", true), Heard::aborting);
  EXPECT_EQ(heard("ps", true), Heard::stopped);  // its word, then its process ends
  EXPECT_EQ(heard("ps", false), Heard::stopped);
  EXPECT_EQ(heard("pp", true), Heard::closed);    // pulses, then gone without a word
  EXPECT_EQ(heard("px1;", true), Heard::failed);  // its own error, then its process ends
  EXPECT_EQ(heard("px1;", false), Heard::failed);
}

// "x" + the exit code in decimal + ";": digits never read as another word.
TEST(Liveness, AFailedWordCarriesItsExitCode) {
  EXPECT_EQ(failed_word(3), "x3;");
  EXPECT_EQ(failed_word(101), "x101;");  // 'e' is 101: as digits, not a good end
  EXPECT_EQ(heard(failed_word(101), true), Heard::failed);
  EXPECT_EQ(failed_code("ppx1;"), 1);
  EXPECT_EQ(failed_code("px255;p"), 255);
  EXPECT_EQ(failed_code("px12"), -1);  // cut before its end
  EXPECT_EQ(failed_code("px;"), -1);
  EXPECT_EQ(failed_code("pxp1;"), -1);
  EXPECT_EQ(failed_code("x99999999999;"), -1);  // no code is that long
  EXPECT_EQ(failed_code("ppp"), -1);
}

TEST(Liveness, SilenceIsTooLongOnlyPastTheTimeout) {
  const Silence::Clock::time_point t0{};
  Silence s(milliseconds(3000), t0);
  EXPECT_FALSE(s.too_long(t0 + milliseconds(3000)));
  EXPECT_TRUE(s.too_long(t0 + milliseconds(3001)));
  s.heard(t0 + milliseconds(2000));
  EXPECT_FALSE(s.too_long(t0 + milliseconds(5000)));
  EXPECT_TRUE(s.too_long(t0 + milliseconds(5001)));
}

TEST(Liveness, NoWordForSaysTheTimeoutInSeconds) {
  EXPECT_EQ(no_word_for(milliseconds(3000)), "no word for 3 s");
  EXPECT_EQ(no_word_for(milliseconds(500)), "no word for 0.5 s");
}

// Over a real socket pair: pulses, then nothing waiting, then a good end, then a close.
TEST(Liveness, ReadsWhatASocketHolds) {
  int fds[2];
  ASSERT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
  EXPECT_EQ(read_liveness(fds[0]), Heard::nothing);
  send_liveness(fds[1], kLivenessPulse);
  send_liveness(fds[1], kLivenessPulse);
  EXPECT_EQ(read_liveness(fds[0]), Heard::pulse);
  EXPECT_EQ(read_liveness(fds[0]), Heard::nothing);
  send_liveness(fds[1], kLivenessEnded);
  close(fds[1]);
  EXPECT_EQ(read_liveness(fds[0]), Heard::ended);
  EXPECT_EQ(read_liveness(fds[0]), Heard::closed);
  close(fds[0]);
}

// A rank's own error: its word with the code, then its close; the code comes out.
TEST(Liveness, ReadsAFailedWordAndItsCode) {
  int fds[2];
  ASSERT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
  send_liveness(fds[1], kLivenessPulse);
  send_liveness(fds[1], failed_word(4));
  close(fds[1]);
  int code = -1;
  EXPECT_EQ(read_liveness(fds[0], &code), Heard::failed);
  EXPECT_EQ(code, 4);
  close(fds[0]);
}

// Everything `fd` receives until its end (blocking, a second at most a read); `reset` tells
// whether that end was a reset rather than the peer's orderly close.
std::string read_to_end(int fd, bool& reset) {
  std::string bytes;
  char c[64];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 1000) <= 0) break;
    const ssize_t n = recv(fd, c, sizeof c, MSG_DONTWAIT);
    if (n > 0) {
      bytes.append(c, static_cast<std::size_t>(n));
      continue;
    }
    reset = n < 0 && errno == ECONNRESET;
    break;
  }
  return bytes;
}

// The coordinator's last word while the rank's pulses lie unread on its end (as they do once
// its watch has stopped): closed right after, the connection must end in order (FIN), not in a
// reset, which would throw away a word not yet on the wire and leave the rank to take the end
// for a crash.
TEST(Liveness, ALastWordEndsTheConnectionInOrderOverUnreadPulses) {
  const Fd listener = listen_tcp("127.0.0.1", 0);
  const Fd rank = connect_tcp("127.0.0.1", local_port(listener.get()), milliseconds(3000), "test");
  pollfd p{listener.get(), POLLIN, 0};
  ASSERT_EQ(poll(&p, 1, 3000), 1);
  int coordinator = accept(listener.get(), nullptr, nullptr);
  ASSERT_GE(coordinator, 0);
  for (int i = 0; i < 3; ++i) send_liveness(rank.get(), kLivenessPulse);
  usleep(50 * 1000);  // the pulses are in the coordinator's receive queue, unread
  send_liveness(coordinator, kLivenessPulse);
  send_last_word(coordinator, kLivenessAborting);
  close(coordinator);
  bool reset = false;
  EXPECT_EQ(read_to_end(rank.get(), reset), "pa");
  EXPECT_FALSE(reset);
}

}  // namespace
}  // namespace l2
