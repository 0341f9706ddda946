// The per-run secret that keeps strangers off the tile port. l2wall makes one for every run and
// hands it to the compositing server and its pipeservers in the environment (L2_VIZ_TOKEN; an
// environment, unlike a command line, is not readable by other users); a pipeserver puts it in
// its HELLO, and a HELLO without it is refused whatever id it claims. It is sent in the clear:
// it stops peers that cannot see the traffic, not ones that can.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace l2::viz {

inline constexpr std::size_t kTokenBytes = 16;
using RunToken = std::array<std::uint8_t, kTokenBytes>;  // all zero: no token (an open server)

inline constexpr const char* kTokenVariable = "L2_VIZ_TOKEN";

// 16 bytes from the kernel's random source. Throws NetError if it cannot be read.
RunToken new_run_token();
// 32 lowercase hex digits.
std::string token_text(const RunToken& token);
// The token written as 32 hex digits, or nullopt.
std::optional<RunToken> parse_token(std::string_view text);
// L2_VIZ_TOKEN from this process's environment; all zero when it is not set. Throws NetError
// naming the variable when it is set but not 32 hex digits.
RunToken token_from_environment();
// Compared in time independent of where they differ, so timing does not reveal the token.
bool same_token(const RunToken& a, const RunToken& b);

}  // namespace l2::viz
