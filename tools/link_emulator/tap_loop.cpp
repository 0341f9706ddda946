#include "tap_loop.hpp"

#include <fcntl.h>
#include <linux/if_tun.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <random>

#include <fmt/format.h>

#include "base/fd.hpp"
#include "base/stop_signals.hpp"

namespace l2::link_emulation {

namespace {

// The largest frame a tap without offloads passes: the MTU's 1500 and the Ethernet header,
// with room for a larger MTU set on the hosts' side.
constexpr std::size_t kFrameBuffer = 65536;
// Frames read from one tap before the others are looked at, so that one busy host does not
// hold the rest back.
constexpr int kFramesPerTurn = 64;
// The longest sleep without a frame due: a stop signal is seen at least this often.
constexpr Nanoseconds kLongestWait = std::chrono::milliseconds(200);

Nanoseconds now() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return Nanoseconds{std::int64_t{t.tv_sec} * 1000000000 + t.tv_nsec};
}

Result<Fd> attach_tap(const std::string& name) {
  if (name.empty() || name.size() >= IFNAMSIZ)
    return Failure{
        fmt::format("tap '{}': not a device name (1 to {} characters)", name, IFNAMSIZ - 1)};
  // TUNSETIFF would make a device of a name that has none, one nothing else is joined to.
  if (::if_nametoindex(name.c_str()) == 0)
    return Failure{
        fmt::format("tap '{}': no such device (ip tuntap add dev {} mode tap)", name, name)};
  Fd fd(::open("/dev/net/tun", O_RDWR | O_NONBLOCK | O_CLOEXEC));
  if (!fd) return Failure{fmt::format("/dev/net/tun: {}", std::strerror(errno))};
  ifreq request{};
  std::memcpy(request.ifr_name, name.data(), name.size());
  request.ifr_flags = IFF_TAP | IFF_NO_PI;
  if (::ioctl(fd.get(), TUNSETIFF, &request) != 0)
    return Failure{fmt::format("tap '{}': cannot attach: {}", name, std::strerror(errno))};
  return fd;
}

}  // namespace

Result<TapLoopEnd> carry_frames(const TapLoopOptions& options, void (*ready)()) {
  std::vector<Fd> taps;
  std::vector<pollfd> polled;
  for (const std::string& name : options.taps) {
    Result<Fd> tap = attach_tap(name);
    if (!tap.ok()) return Failure{tap.reason()};
    polled.push_back(pollfd{tap->get(), POLLIN, 0});
    taps.push_back(std::move(tap).value());
  }
  ready();
  LearningSwitch ports(static_cast<int>(taps.size()));
  HeldFrames held(options.limit);
  std::mt19937_64 random(options.seed);
  TapLoopEnd end;
  std::vector<std::uint8_t> frame(kFrameBuffer);
  const auto send = [&](int port, std::span<const std::uint8_t> bytes) {
    if (::write(taps[static_cast<std::size_t>(port)].get(), bytes.data(), bytes.size()) < 0)
      ++end.not_taken;
  };
  while (stop_signal_received() == 0 && end.gone.empty()) {
    held.release_due(now(), send);
    const Nanoseconds wait =
        held.empty() ? kLongestWait
                     : std::clamp(held.next_release() - now(), Nanoseconds{0}, kLongestWait);
    const timespec timeout{static_cast<time_t>(wait.count() / 1000000000),
                           static_cast<long>(wait.count() % 1000000000)};
    if (::ppoll(polled.data(), polled.size(), &timeout, nullptr) < 0) {
      if (errno == EINTR) continue;
      return Failure{fmt::format("ppoll: {}", std::strerror(errno))};
    }
    for (std::size_t in = 0; in < polled.size(); ++in) {
      if ((polled[in].revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
        end.gone = options.taps[in];
        break;
      }
      if ((polled[in].revents & POLLIN) == 0) continue;
      for (int turn = 0; turn < kFramesPerTurn; ++turn) {
        const ssize_t n = ::read(polled[in].fd, frame.data(), frame.size());
        if (n < 0) {
          // EAGAIN: read all there was; anything else: the device is no more.
          if (errno != EAGAIN && errno != EINTR) end.gone = options.taps[in];
          break;
        }
        const std::span<const std::uint8_t> bytes(frame.data(), static_cast<std::size_t>(n));
        if (bytes.size() < kEthernetHeader) {
          ++end.too_short;
          continue;
        }
        const Nanoseconds arrival = now();
        const Nanoseconds release = arrival + hold_for(options.link, random());
        for (const int out : ports.destinations(static_cast<int>(in), bytes))
          held.hold(arrival, release, out, bytes);
      }
    }
  }
  end.held = held.counts();
  return end;
}

std::string describe(const TapLoopOptions& options, const TapLoopEnd& end) {
  const auto ms = [](Nanoseconds t) { return static_cast<double>(t.count()) / 1e6; };
  const HeldCounts& held = end.held;
  std::string line = fmt::format(
      "{} frames ({:.1f} MB) carried between {} host{}, each held {:g} ± {:g} ms", held.frames,
      static_cast<double>(held.bytes) / 1e6, options.taps.size(),
      options.taps.size() == 1 ? "" : "s", ms(options.link.delay), ms(options.link.jitter));
  if (held.frames > 0) {
    line += fmt::format(": held {:.1f} to {:.1f} ms, mean {:.2f} ms", ms(held.least), ms(held.most),
                        ms(held.total) / static_cast<double>(held.frames));
  }
  line += fmt::format(
      "; dropped {} past the {} held at once, {} shorter than a header, {} "
      "a host did not take",
      held.over_limit, options.limit, end.too_short, end.not_taken);
  if (!end.gone.empty()) line += fmt::format("; ended: tap {} went away", end.gone);
  return line;
}

}  // namespace l2::link_emulation
