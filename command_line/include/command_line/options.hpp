// The options that mean the same thing in every program, added by one function each so that
// they are spelled, typed, checked and explained the same way everywhere (tests/usage_errors.sh
// compares the --help of every program):
//   --wall FILE      the wall file; never a positional argument
//   --refresh HZ     a rate in Hz (refreshes, frames or READY lines per second)
//   --*-timeout MS   every timeout in milliseconds, typed MS in the help
//   --threads N      routing threads, one default
//   --out DIR        an output folder, never a file
//
// Example:
//
//   std::filesystem::path wall, out;
//   double refresh_hz = 60;
//   int ready_timeout_ms = 1000, threads = 1;
//   l2::add_wall_option(app, wall, "default: the built-in default wall (walls/kd-2x2.toml)");
//   l2::add_refresh_option(app, refresh_hz, true, "refreshes per second; 0 = as fast as possible");
//   l2::add_timeout_option(app, "ready-timeout", ready_timeout_ms, false,
//                          "per READY wait before asking again with SYNC?");
//   l2::add_threads_option(app, threads);
//   l2::add_out_option(app, out, "the displays and the report")->required();
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <string>

#include "command_line/checks.hpp"

namespace l2 {

// The emulator's routing threads unless --threads says otherwise: one, because in a live run
// the pipeservers need the other cores, and one default everywhere keeps a run and a replay
// of its frames alike.
inline constexpr int kDefaultThreads = 1;
inline constexpr int kMaxThreads = 64;

// --wall FILE: an existing wall file. `what` says what the wall is for and what happens
// without one.
template <class Path>
CLI::Option* add_wall_option(CLI::App& app, Path& wall, const std::string& what) {
  return app.add_option("--wall", wall, "wall file (TOML, docs/wall-file.md); " + what)
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
}

// --refresh HZ: 1..1000 Hz, or 0 (as fast as possible) where `zero_allowed`.
inline CLI::Option* add_refresh_option(CLI::App& app, double& hz, bool zero_allowed,
                                       const std::string& what) {
  return app.add_option("--refresh", hz, what)->type_name("HZ")->check(rate_hz(zero_allowed));
}

// A timeout in milliseconds: 1..86400000, or 0 (wait forever) where `zero_forever`.
inline CLI::Validator timeout_ms(bool zero_forever) {
  constexpr long long kMaxMs = 86400000;  // a day
  return CLI::Validator(
      [zero_forever](std::string& text) -> std::string {
        long long ms = -1;
        const char* const end = text.data() + text.size();
        const auto [stop, ec] = std::from_chars(text.data(), end, ms);
        const bool number = !text.empty() && ec == std::errc{} && stop == end;
        if (number && ((zero_forever && ms == 0) || (ms >= 1 && ms <= kMaxMs))) return {};
        return text +
               (zero_forever ? " is not 0 (forever) or 1..86400000 ms" : " is not 1..86400000 ms");
      },
      zero_forever ? "0 (forever) or 1..86400000" : "1..86400000");
}

// --NAME-timeout MS: `name` without the dashes ("stall-timeout").
template <class Int>
CLI::Option* add_timeout_option(CLI::App& app, const std::string& name, Int& ms, bool zero_forever,
                                const std::string& what) {
  return app.add_option("--" + name, ms, "ms " + what)
      ->type_name("MS")
      ->check(timeout_ms(zero_forever))
      ->capture_default_str();
}

// --threads N: 0 (one per core) .. kMaxThreads; the default is kDefaultThreads.
inline CLI::Option* add_threads_option(CLI::App& app, int& threads) {
  threads = kDefaultThreads;
  return app.add_option("--threads", threads, "emulator routing threads (0: one per core)")
      ->type_name("N")
      ->check(CLI::Range(0, kMaxThreads))
      ->capture_default_str();
}

// --out DIR: an output folder (made if missing), not empty.
template <class Path>
CLI::Option* add_out_option(CLI::App& app, Path& out, const std::string& what) {
  return app.add_option("--out", out, "output folder (made if missing): " + what)
      ->type_name("DIR")
      ->check(non_empty_path());
}

}  // namespace l2
