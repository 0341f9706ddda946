// The READY protocol end to end over real pseudo-terminals: the emulator end on the master, the
// host end on the slave, each in its own thread where both must run at once.
#include "sync_backchannel/back_channel.hpp"

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "sync_backchannel/pty_pair.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// One back-channel line. `open_host` false leaves the host end closed, so that what the
// emulator sends is dropped when the host opens it (SerialPort::open discards queued bytes).
struct Line {
  explicit Line(bool open_host = true) {
    if (open_host) connect_host();
  }
  void connect_host() {
    host_port.emplace(SerialPort::open(pty.slave_path(), 115200));
    host.emplace(*host_port);
  }
  PtyPair pty = PtyPair::open();
  BackChannel emulator{pty.master()};
  std::optional<SerialPort> host_port;
  std::optional<BackChannel> host;
};

// Emulator end that answers SYNC? until one was answered or `limit` passed.
void serve_until_answered(BackChannel& emulator, std::chrono::milliseconds limit) {
  const auto deadline = Clock::now() + limit;
  while (Clock::now() < deadline && emulator.serve(20ms) == 0) {
  }
}

std::string read_for(SerialPort& port, std::chrono::milliseconds duration) {
  std::string out;
  const auto deadline = Clock::now() + duration;
  std::uint8_t buffer[64];
  while (Clock::now() < deadline) {
    const std::size_t n = port.read(buffer, 20ms);
    out.append(reinterpret_cast<const char*>(buffer), n);
  }
  return out;
}

TEST(BackChannel, HostReceivesEachReadyInOrder) {
  Line line;
  std::thread emulator([&] {
    for (int frame = 0; frame < 20; ++frame) line.emulator.send_ready(frame);
  });
  for (int frame = 0; frame < 20; ++frame) {
    const Result<ReadyAck> r = line.host->wait_ready(frame, 500ms, 0);
    ASSERT_TRUE(r.ok()) << r.reason();
    EXPECT_EQ(r->frame, static_cast<std::uint32_t>(frame));
    EXPECT_EQ(r->retries, 0);
  }
  emulator.join();
  EXPECT_EQ(line.host->counts().parser.messages, 20u);
  EXPECT_EQ(line.host->counts().parser.noise_bytes, 0u);
  EXPECT_EQ(line.host->counts().stale, 0u);
  EXPECT_EQ(line.emulator.counts().ready_sent, 20u);
}

TEST(BackChannel, NoiseInjectedOnTheMasterIsSkippedAndCounted) {
  Line line;
  // Glitches from the emulator side: garbage, a torn message, then the real READY.
  line.pty.master().write_all(std::string("\x00\xff~~READY 0000", 14), 100ms);
  line.emulator.send_ready(7);
  const Result<ReadyAck> r = line.host->wait_ready(7, 500ms, 0);
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 7u);
  EXPECT_EQ(line.host->counts().parser.noise_bytes, 14u);
  EXPECT_EQ(line.host->counts().parser.resyncs, 1u);
  EXPECT_EQ(line.host->counts().parser.messages, 1u);
}

TEST(BackChannel, ADroppedReadyIsRecoveredWithOneSyncRequest) {
  Line line(/*open_host=*/false);
  line.emulator.send_ready(5);  // lost: the host is not listening yet
  line.connect_host();
  std::thread emulator([&] { serve_until_answered(line.emulator, 2s); });
  const auto start = Clock::now();
  const Result<ReadyAck> r = line.host->wait_ready(5, 100ms, 3);
  const auto took = Clock::now() - start;
  emulator.join();
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 5u);
  EXPECT_EQ(r->retries, 1);
  EXPECT_GE(took, 100ms);
  EXPECT_LT(took, 1s);
  EXPECT_EQ(line.host->counts().wait_timeouts, 1u);
  EXPECT_EQ(line.host->counts().sync_sent, 1u);
  EXPECT_EQ(line.emulator.counts().sync_answered, 1u);
  EXPECT_EQ(line.emulator.counts().ready_sent, 2u);  // the lost one and its repeat
}

TEST(BackChannel, ACorruptedReadyCountsABadChecksumAndIsRecovered) {
  Line line(/*open_host=*/false);
  line.emulator.send_ready(5);
  line.connect_host();
  // What reaches the host instead of READY 5: the same line with one digit hit by noise.
  line.pty.master().write_all("READY 000006 3D\r\n", 100ms);
  std::thread emulator([&] { serve_until_answered(line.emulator, 2s); });
  const Result<ReadyAck> r = line.host->wait_ready(5, 100ms, 3);
  emulator.join();
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 5u);
  EXPECT_EQ(r->retries, 1);
  EXPECT_EQ(line.host->counts().parser.bad_checksums, 1u);
  EXPECT_EQ(line.host->counts().parser.messages, 1u);
}

TEST(BackChannel, StaleAndDuplicateReadysAreIgnoredAndNewerOnesAccepted) {
  Line line;
  line.emulator.send_ready(3);
  ASSERT_TRUE(line.host->wait_ready(3, 300ms, 0).ok());
  line.emulator.send_ready(3);  // duplicate of the one accepted
  line.emulator.send_ready(1);  // stale
  line.emulator.send_ready(4);
  Result<ReadyAck> r = line.host->wait_ready(4, 300ms, 0);
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 4u);
  EXPECT_EQ(line.host->counts().duplicates, 1u);
  EXPECT_EQ(line.host->counts().stale, 1u);
  // The emulator is already past the frame we wait for: swapping is safe, accept it.
  line.emulator.send_ready(8);
  r = line.host->wait_ready(6, 300ms, 0);
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 8u);
  EXPECT_EQ(line.host->counts().ahead, 1u);
}

TEST(BackChannel, FrameNumbersWrapAroundAtAMillion) {
  Line line;
  line.emulator.send_ready(999'999);
  ASSERT_TRUE(line.host->wait_ready(999'999, 300ms, 0).ok());
  line.emulator.send_ready(1'000'000);  // travels as 000000
  const Result<ReadyAck> r = line.host->wait_ready(1'000'000, 300ms, 0);
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 0u);
  EXPECT_EQ(line.host->counts().stale, 0u);
}

TEST(BackChannel, HostGivesUpAfterItsRetriesWithAClearErrorAndCarriesOn) {
  Line line;
  const auto start = Clock::now();
  const Result<ReadyAck> r = line.host->wait_ready(9, 60ms, 2);
  const auto took = Clock::now() - start;
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.reason(), "no READY for frame 000009 on " + line.pty.slave_path() +
                            " after 2 SYNC? retries (3 waits of 60 ms)");
  EXPECT_GE(took, 180ms);
  EXPECT_LT(took, 10 * 180ms);  // the three waits, with room for a loaded machine's wake-ups
  EXPECT_EQ(line.host->counts().wait_timeouts, 3u);
  // Exactly the two requests the protocol prescribes reached the emulator end.
  EXPECT_EQ(read_for(line.pty.master(), 100ms), "SYNC? 000009 D1\r\nSYNC? 000009 D1\r\n");
  // The run goes on: the next READY is taken normally.
  line.emulator.send_ready(10);
  EXPECT_TRUE(line.host->wait_ready(10, 300ms, 0).ok());
}

TEST(BackChannel, SyncRequestBeforeAnyReadyIsCountedUnanswered) {
  Line line;
  line.host->send_sync_request(0);
  EXPECT_EQ(line.emulator.serve(100ms), 0);
  EXPECT_EQ(line.emulator.counts().sync_unanswered, 1u);
  EXPECT_EQ(line.emulator.counts().ready_sent, 0u);
}

TEST(BackChannel, SlowByteByByteWriterStillDelivers) {
  Line line;
  const std::string ready = "READY 000042 7C\r\n";
  std::thread slow([&] {
    for (char c : ready) {
      line.pty.master().write_all(std::string_view(&c, 1), 100ms);
      std::this_thread::sleep_for(4ms);
    }
  });
  const Result<ReadyAck> r = line.host->wait_ready(42, 800ms, 0);
  slow.join();
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, 42u);
  EXPECT_EQ(line.host->counts().parser.noise_bytes, 0u);
}

// A host that stops reading fills its line. The emulator must not wait for it (it would hold
// up every display); READYs are dropped and counted, and the host recovers with SYNC?.
TEST(BackChannel, AHostThatStoppedReadingNeitherStallsTheEmulatorNorGetsLost) {
  Line line;
  constexpr int kFrames = 3000;  // about 51 KB: more than a pty line holds
  const auto start = Clock::now();
  int dropped = 0;
  // Sent until the last READY is dropped: the kernel moves a pty's bytes to the reader's side
  // in the background, so a write after the first drop may find room again, and a READY that
  // got through would be read from the backlog without a SYNC?.
  int frames = 0;
  for (bool last_dropped = false; frames < kFrames || !last_dropped; ++frames) {
    ASSERT_LT(frames, 2 * kFrames) << "the line never filled";
    last_dropped = !line.emulator.send_ready(frames);
    dropped += last_dropped;
  }
  EXPECT_LT(Clock::now() - start, 500ms);
  EXPECT_GT(dropped, 0);
  EXPECT_EQ(line.emulator.counts().ready_dropped, static_cast<std::uint64_t>(dropped));
  EXPECT_EQ(line.emulator.counts().ready_sent, static_cast<std::uint64_t>(frames));
  // The host reads again: the backlog is stale, the last READY was dropped, SYNC? brings it.
  std::thread emulator([&] { serve_until_answered(line.emulator, 3s); });
  const Result<ReadyAck> r = line.host->wait_ready(frames - 1, 150ms, 5);
  emulator.join();
  ASSERT_TRUE(r.ok()) << r.reason();
  EXPECT_EQ(r->frame, static_cast<std::uint32_t>(frames - 1));
  EXPECT_GE(r->retries, 1);
  EXPECT_GT(line.host->counts().stale, 0u);
}

TEST(BackChannel, CountsReadAsOneLine) {
  BackChannelCounts c;
  c.parser.messages = 3;
  c.parser.noise_bytes = 2;
  c.duplicates = 1;
  EXPECT_EQ(to_string(c),
            "decoded 3, noise bytes 2, resyncs 0, bad checksums 0, READY sent 0, READY dropped 0, "
            "SYNC? sent 0, "
            "SYNC? answered 0, SYNC? unanswered 0, wait timeouts 0, stale 0, duplicates 1, "
            "ahead 0, unexpected 0");
}

}  // namespace
}  // namespace l2
