// link_emulator: the switch between the hosts of scripts/cluster.sh when their links are to
// delay packets (--delay, --jitter), which this machine's kernel, without netem, cannot do
// itself. Each host's link is a tap device in its namespace; this program holds the taps'
// other ends, passes each frame on to the host it is for (a learning switch) after holding it
// for the link's delay, and on SIGTERM or SIGINT prints what it carried, held and dropped.
#include <sys/prctl.h>

#include <csignal>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "base/stop_signals.hpp"
#include "command_line/parse.hpp"
#include "tap_loop.hpp"

namespace {

void say_ready() {
  std::puts("link_emulator: ready");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "link_emulator: a switch between tap devices that holds every frame a host sends for a "
      "delay with jitter, as `tc netem delay D J` on every host's link would (scripts/cluster.sh "
      "--delay). Prints 'link_emulator: ready' once every tap is attached; on SIGTERM or SIGINT, "
      "one line of what it carried, how long frames were held and what it dropped."};
  l2::link_emulation::TapLoopOptions options;
  double delay_ms = 0, jitter_ms = 0;
  app.add_option("--tap", options.taps,
                 "a persistent tap device to attach to (`ip tuntap add dev NAME mode tap`), one "
                 "per host; repeat it for each")
      ->type_name("NAME")
      ->required();
  app.add_option("--delay", delay_ms, "each frame held this long, 0..10000")
      ->type_name("MS")
      ->check(CLI::Range(0.0, 10000.0))
      ->capture_default_str();
  app.add_option("--jitter", jitter_ms,
                 "each frame's hold drawn uniformly from --delay ± this, never below 0; 0..10000")
      ->type_name("MS")
      ->check(CLI::Range(0.0, 10000.0))
      ->capture_default_str();
  app.add_option("--limit", options.limit,
                 "frames held at once, 1..1000000; a frame past them is dropped and counted "
                 "(netem's queue limit)")
      ->type_name("FRAMES")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_option("--seed", options.seed, "the jitter's random numbers")->capture_default_str();
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;

  const auto ns = [](double ms) {
    return l2::link_emulation::Nanoseconds{static_cast<long long>(ms * 1e6)};
  };
  options.link = {ns(delay_ms), ns(jitter_ms)};
  l2::catch_stop_signals();
  // Ended with the script that started it, however that ends: no switch left behind.
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  const l2::Result<l2::link_emulation::TapLoopEnd> end =
      l2::link_emulation::carry_frames(options, say_ready);
  if (!end.ok()) {
    fmt::print(stderr, "link_emulator: {}\n", end.reason());
    return 1;
  }
  fmt::print("link_emulator: {}\n", l2::link_emulation::describe(options, *end));
  return 0;
}
