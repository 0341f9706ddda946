// sync_backchannel: the serial back-channel of spec §6 from a shell. Plays either end of the
// READY protocol on a real serial port or a pseudo-terminal, and lets a person watch the line.
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/pty_pair.hpp"
#include "sync_backchannel/serial_port.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) {
  g_stop = 1;
}

void stop_on_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

// Emulator end on a fresh pty pair: READY `refresh_hz` times a second, SYNC? answered in
// between.
int run_pty(double refresh_hz, long long count, long long start) {
  const auto period = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::duration<double>(1.0 / refresh_hz));
  stop_on_signals();
  l2::PtyPair pty = l2::PtyPair::open();
  std::cout << pty.slave_path() << std::endl;  // first line: where the host connects
  l2::BackChannel channel(pty.master());
  for (long long sent = 0; !g_stop && (count == 0 || sent < count); ++sent) {
    // A host that is not reading fills the line; the READY is dropped and counted, and the
    // host recovers through SYNC? when it reads again.
    channel.send_ready(static_cast<std::uint64_t>(start + sent));
    channel.serve(period);
  }
  std::cerr << "sync_backchannel pty: " << l2::to_string(channel.counts()) << '\n';
  return 0;
}

int run_send_ready(const std::string& device, int baud, long long frame) {
  l2::SerialPort port = l2::SerialPort::open(device, baud);
  if (!l2::BackChannel(port).send_ready(static_cast<std::uint64_t>(frame))) {
    std::cerr << "sync_backchannel: " << device << " is full (nobody reads it); READY dropped\n";
    return 1;
  }
  return 0;
}

int run_wait_ready(const std::string& device, int baud, long long frame, int timeout_ms,
                   int retries) {
  l2::SerialPort port = l2::SerialPort::open(device, baud);
  l2::BackChannel channel(port);
  const l2::Result<l2::ReadyAck> result = channel.wait_ready(
      static_cast<std::uint64_t>(frame), std::chrono::milliseconds(timeout_ms), retries);
  if (!result.ok()) {
    std::cerr << "sync_backchannel: " << result.reason() << '\n';
    std::cerr << "sync_backchannel wait-ready: " << l2::to_string(channel.counts()) << '\n';
    return 1;
  }
  std::cout << fmt::format("READY {:06d} after {} retries\n", result->frame, result->retries);
  std::cerr << "sync_backchannel wait-ready: " << l2::to_string(channel.counts()) << '\n';
  return 0;
}

int run_watch(const std::string& device, int baud, int duration_ms, long long count) {
  stop_on_signals();
  l2::SerialPort port = l2::SerialPort::open(device, baud);
  // Only after opening: bytes that arrived earlier were discarded by the open.
  std::cerr << "watching " << device << std::endl;
  l2::MessageParser parser;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(duration_ms);
  std::uint8_t buffer[256];
  long long decoded = 0;
  while (!g_stop && (duration_ms == 0 || std::chrono::steady_clock::now() < deadline) &&
         (count == 0 || decoded < count)) {
    const std::size_t n = port.read(buffer, std::chrono::milliseconds(50));
    parser.feed(std::span<const std::uint8_t>(buffer, n), [&](const l2::Message& m) {
      std::cout << l2::to_string(m) << std::endl;
      ++decoded;
    });
  }
  const l2::ParserCounts& c = parser.counts();
  std::cout << fmt::format("decoded {}, noise bytes {}, resyncs {}, bad checksums {}\n", c.messages,
                           c.noise_bytes, c.resyncs, c.bad_checksums);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "The Lightning-2 serial back-channel (spec section 6). The emulator sends one ASCII line\n"
      "\"READY <6-digit frame> <2-hex CRC-8>\\r\\n\" per swap; a host that misses it asks\n"
      "\"SYNC? <frame> <crc>\\r\\n\" and gets the last READY again. See docs/ready-protocol.md.\n"
      "Watch a line by hand with: socat -u FILE:/dev/pts/N,raw,echo=0 -",
      "sync_backchannel"};
  app.require_subcommand(1);
  int baud = l2::kDefaultBaud;
  std::string device;
  long long frame = 0;

  CLI::App* pty = app.add_subcommand(
      "pty",
      "Emulator end on a new pseudo-terminal pair: prints the slave path (the host's "
      "device) on the first line, then sends READY --refresh times a second and answers SYNC?");
  double refresh_hz = 10;
  long long count = 0;
  l2::add_refresh_option(*pty, refresh_hz, false, "READY lines per second")->capture_default_str();
  pty->add_option("--count", count, "Send this many READY lines, then exit (0: until SIGINT)")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  // Below 10^6, as READY carries it, so that --start plus the lines sent cannot overflow.
  pty->add_option("--start", frame, "Frame number of the first READY (0..999999)")
      ->default_val(0)
      ->check(CLI::Range(0LL, 999999LL));

  auto add_device = [&](CLI::App* cmd) {
    cmd->add_option("device", device, "Serial device, e.g. /dev/ttyUSB0 or /dev/pts/3")->required();
    cmd->add_option("--baud", baud, "Baud rate (ignored by pseudo-terminals)")
        ->default_val(l2::kDefaultBaud);
  };

  CLI::App* send = app.add_subcommand("send-ready", "Emulator end: send one READY line");
  add_device(send);
  send->add_option("--frame", frame, "Frame number to announce (sent modulo 1000000)")
      ->required()
      ->check(l2::frame_number());

  CLI::App* wait =
      app.add_subcommand("wait-ready",
                         "Host end: wait for READY of --frame, retrying with SYNC? as the protocol "
                         "says; exit status 1 with one error line when it never comes");
  add_device(wait);
  int timeout_ms = static_cast<int>(l2::kDefaultReadyTimeout.count());
  int retries = l2::kDefaultReadyRetries;
  wait->add_option("--frame", frame, "Frame number awaited (modulo 1000000)")
      ->required()
      ->check(l2::frame_number());
  // Named as pipeserver's options of the same waits.
  l2::add_timeout_option(*wait, "ready-timeout", timeout_ms, false,
                         "per READY wait before asking again with SYNC?");
  wait->add_option("--ready-retries", retries, "SYNC? retries before giving up")
      ->default_val(retries)
      ->check(CLI::Range(0, 1000));

  CLI::App* watch = app.add_subcommand(
      "watch", "Print every decoded message on a line, then the noise/resync/checksum counts");
  add_device(watch);
  int duration_ms = 0;
  watch->add_option("--duration", duration_ms, "ms to watch for (0: until SIGINT)")
      ->type_name("MS")
      ->default_val(0)
      ->check(l2::timeout_ms(true));
  long long watch_count = 0;
  watch->add_option("--count", watch_count, "Stop after this many decoded messages (0: no limit)")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);

  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    if (*pty) return run_pty(refresh_hz, count, frame);
    if (*send) return run_send_ready(device, baud, frame);
    if (*wait) return run_wait_ready(device, baud, frame, timeout_ms, retries);
    if (*watch) return run_watch(device, baud, duration_ms, watch_count);
  } catch (const l2::SerialError& e) {
    std::cerr << "sync_backchannel: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
