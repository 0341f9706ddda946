// Checks for option values that CLI11's own validators let through: CLI::Range passes NaN
// (every comparison with it is false), CLI11 clamps an integer too large for its type, and an
// empty path means the current folder. Timeouts: command_line/options.hpp.
//
// Example:
//
//   CLI::App app{"my_program: ..."};
//   float fov = 45;
//   long long frame = 0;
//   std::string screenshots;
//   app.add_option("--camera-fov", fov, "vertical field of view in degrees")
//       ->check(l2::number_in(1, 170));
//   app.add_option("--frame", frame, "frame to show")->check(l2::frame_number());
//   app.add_option("--screenshots", screenshots, "folder")->check(l2::non_empty_path());
//   // --refresh: l2::add_refresh_option (options.hpp) checks with l2::rate_hz(zero_allowed)
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace l2 {

inline constexpr double kMinRateHz = 1, kMaxRateHz = 1000;

// A refresh or frame rate in Hz: 1..1000, or 0 (as fast as possible) where allowed. Below
// 1 Hz a run sleeps through seconds between refreshes, past its stall timeout and its stop
// signal, and 1e-10 Hz overflowed the period.
inline CLI::Validator rate_hz(bool zero_allowed) {
  return CLI::Validator(
      [zero_allowed](std::string& text) -> std::string {
        const double hz = std::strtod(text.c_str(), nullptr);
        if ((zero_allowed && hz == 0) || (hz >= kMinRateHz && hz <= kMaxRateHz)) return {};
        return text + (zero_allowed ? " is not 0 (as fast as possible) or 1..1000 Hz"
                                    : " is not 1..1000 Hz");
      },
      zero_allowed ? "0 or 1..1000 Hz" : "1..1000 Hz");
}

// A number lo..hi, NaN refused (CLI::Range lets it through).
inline CLI::Validator number_in(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && v >= lo && v <= hi) return {};
        return text + " is not a number in " + CLI::detail::to_string(lo) + ".." +
               CLI::detail::to_string(hi);
      },
      CLI::detail::to_string(lo) + ".." + CLI::detail::to_string(hi));
}

// A frame number: digits only, fitting a long long. CLI11 clamps a larger number to the
// largest long long without a word (18446744073709551616 became 9223372036854775807).
inline CLI::Validator frame_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        long long value = 0;
        const char* const end = text.data() + text.size();
        const auto [stop, ec] = std::from_chars(text.data(), end, value);
        if (!text.empty() && text[0] != '-' && ec == std::errc{} && stop == end) return {};
        return text + " is not a frame number 0..9223372036854775807";
      },
      "FRAME");
}

// An output path: not empty, which would mean the current folder without saying so.
inline CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "an empty path (give a folder; '.' for the current one)" : "";
      },
      "PATH");
}

}  // namespace l2
