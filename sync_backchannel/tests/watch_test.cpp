// "A person can watch it": the READY line seen through socat, a standard terminal tool, on the
// pseudo-terminal a host would use; and the sync_backchannel executable end to end.
#include <signal.h>

#include <chrono>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "base/child_process.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/pty_pair.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kExe = L2_SYNC_BACKCHANNEL_EXE;

std::string read_for(SerialPort& port, std::chrono::milliseconds duration) {
  std::string out;
  const auto deadline = std::chrono::steady_clock::now() + duration;
  std::uint8_t buffer[64];
  while (std::chrono::steady_clock::now() < deadline) {
    out.append(reinterpret_cast<const char*>(buffer), port.read(buffer, 20ms));
  }
  return out;
}

// socat reading the host's end, exactly as a person would type it; -T ends it 0.3 s after the
// line goes quiet, `timeout` bounds it whatever happens.
std::vector<std::string> socat_watch(const std::string& slave) {
  return {"timeout", "-s", "INT", "5", "socat", "-u", "-T", "0.3", "FILE:" + slave + ",raw,echo=0",
          "STDOUT"};
}

TEST(WatchWithSocat, SocatSeesTheExactReadyLines) {
  PtyPair pty = PtyPair::open();
  BackChannel emulator(pty.master());
  // Queued on the line before socat opens it; socat, unlike a host, does not discard them.
  emulator.send_ready(123);
  emulator.send_ready(124);
  const Finished r = run(socat_watch(pty.slave_path()), 5s);
  EXPECT_EQ(r.status.shell_code(), 0) << r.err;
  EXPECT_EQ(r.out, "READY 000123 6E\r\nREADY 000124 7B\r\n");
}

TEST(WatchWithSocat, APersonCanTypeASyncRequestThatTheEmulatorAnswers) {
  PtyPair pty = PtyPair::open();
  BackChannel emulator(pty.master());
  emulator.send_ready(5);
  const Finished r =
      run({"sh", "-c",
           "printf 'SYNC? 000005 F5\\r\\n' | timeout 5 socat -u STDIN FILE:" + pty.slave_path() +
               ",raw,echo=0"},
          5s);
  ASSERT_EQ(r.status.shell_code(), 0) << r.err;
  EXPECT_EQ(emulator.serve(200ms), 1);
  EXPECT_EQ(emulator.counts().sync_answered, 1u);
}

TEST(SyncBackchannelExe, HelpListsEverySubcommand) {
  const Finished r = run({kExe, "--help"}, 5s);
  EXPECT_EQ(r.status.shell_code(), 0);
  for (const char* word : {"pty", "send-ready", "wait-ready", "watch", "READY", "SYNC?"}) {
    EXPECT_THAT(r.out, HasSubstr(word));
  }
  const Finished sub = run({kExe, "wait-ready", "--help"}, 5s);
  EXPECT_THAT(sub.out, HasSubstr("--ready-retries"));
  EXPECT_THAT(sub.out, HasSubstr("--ready-timeout MS"));
}

TEST(SyncBackchannelExe, SendReadyWritesTheExactLine) {
  PtyPair pty = PtyPair::open();
  const Finished r = run({kExe, "send-ready", pty.slave_path(), "--frame", "42"}, 5s);
  ASSERT_EQ(r.status.shell_code(), 0) << r.err;
  EXPECT_EQ(read_for(pty.master(), 100ms), "READY 000042 7C\r\n");
}

TEST(SyncBackchannelExe, BadDeviceIsOneErrorLine) {
  const Finished r = run({kExe, "send-ready", "/dev/l2-nope", "--frame", "1"}, 5s);
  EXPECT_EQ(r.status.shell_code(), 1);
  EXPECT_EQ(r.err,
            "sync_backchannel: cannot open serial device /dev/l2-nope: No such file or "
            "directory\n");
  const Finished baud =
      run({kExe, "watch", "/dev/null", "--baud", "31337", "--duration", "10"}, 5s);
  EXPECT_EQ(baud.status.shell_code(), 1);
  EXPECT_THAT(baud.err, StartsWith("sync_backchannel: unsupported baud rate 31337 for /dev/null"));
}

TEST(SyncBackchannelExe, WatchPrintsDecodedMessagesAndCounts) {
  PtyPair pty = PtyPair::open();
  ChildProcess watch({kExe, "watch", pty.slave_path(), "--count", "2", "--duration", "5000"}, {},
                     Capture{true, true});
  ASSERT_EQ(watch.read_line(Stream::Err, 5s), "watching " + pty.slave_path());
  pty.master().write_all("READY 000001 21\r\n#noise#READ\x01SYNC? 000000 EE\r\n", 100ms);
  const Finished r = watch.finish(5s);
  EXPECT_EQ(r.status.shell_code(), 0) << r.err;
  EXPECT_EQ(r.out,
            "READY 000001\n"
            "SYNC? 000000\n"
            "decoded 2, noise bytes 12, resyncs 1, bad checksums 0\n");
}

TEST(SyncBackchannelExe, WaitReadyReportsATimeoutAsOneLine) {
  PtyPair pty = PtyPair::open();
  const Finished r = run({kExe, "wait-ready", pty.slave_path(), "--frame", "3", "--ready-timeout",
                          "50", "--ready-retries", "1"},
                         5s);
  EXPECT_EQ(r.status.shell_code(), 1);
  EXPECT_THAT(r.err, StartsWith("sync_backchannel: no READY for frame 000003 on " +
                                pty.slave_path() + " after 1 SYNC? retries (2 waits of 50 ms)\n"));
}

TEST(SyncBackchannelExe, PtyEmulatorFeedsAHostAndAWatcher) {
  ChildProcess emulator({kExe, "pty", "--refresh", "33"}, {}, Capture{true, true});
  const std::string slave = emulator.read_line(Stream::Out, 5s).value_or("");
  ASSERT_THAT(slave, StartsWith("/dev/pts/"));
  // A person watching the line sees whole READY lines from frame 0 on (queued on the line
  // since the emulator started; socat, unlike a host, does not discard them).
  const Finished seen = run(
      {"timeout", "-s", "INT", "1", "socat", "-u", "FILE:" + slave + ",raw,echo=0", "STDOUT"}, 5s);
  EXPECT_THAT(seen.out, StartsWith("READY 000000 26\r\nREADY 000001 21\r\n"));
  // A host joining late takes the next READY, whatever frame the emulator has reached.
  SerialPort port = SerialPort::open(slave, 115200);
  BackChannel host(port);
  const Result<ReadyAck> first = host.wait_ready(0, 300ms, 3);
  ASSERT_TRUE(first.ok()) << first.reason();
  const Result<ReadyAck> next = host.wait_ready(first->frame + 1, 300ms, 3);
  ASSERT_TRUE(next.ok()) << next.reason();
  EXPECT_EQ(next->frame, first->frame + 1);
  emulator.signal(SIGTERM);
  const Finished r = emulator.finish(5s);
  EXPECT_EQ(r.status.shell_code(), 0);
  EXPECT_THAT(r.err, HasSubstr("sync_backchannel pty: decoded "));
}

}  // namespace
}  // namespace l2
