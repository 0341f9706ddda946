// What a liveness connection's reader makes of its bytes, and the clock of a peer's silence.
#include "mpi_link/liveness.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

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

}  // namespace
}  // namespace l2
