#include "viz_link/run_token.hpp"

#include <sys/random.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "base/socket.hpp"

namespace l2::viz {

RunToken new_run_token() {
  RunToken token{};
  std::size_t got = 0;
  while (got < token.size()) {
    const ssize_t n = ::getrandom(token.data() + got, token.size() - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw NetError(fmt::format("cannot make a run token: {}", std::strerror(errno)));
    got += static_cast<std::size_t>(n);
  }
  return token;
}

std::string token_text(const RunToken& token) {
  std::string out;
  for (const std::uint8_t b : token) out += fmt::format("{:02x}", b);
  return out;
}

std::optional<RunToken> parse_token(std::string_view text) {
  if (text.size() != 2 * kTokenBytes) return std::nullopt;
  const auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  RunToken token{};
  for (std::size_t i = 0; i < kTokenBytes; ++i) {
    const int hi = nibble(text[2 * i]), lo = nibble(text[2 * i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    token[i] = static_cast<std::uint8_t>(hi << 4 | lo);
  }
  return token;
}

RunToken token_from_environment() {
  const char* value = std::getenv(kTokenVariable);
  if (!value) return RunToken{};
  if (auto token = parse_token(value)) return *token;
  throw NetError(fmt::format("{} is set but is not 32 hex digits", kTokenVariable));
}

bool same_token(const RunToken& a, const RunToken& b) {
  std::uint8_t differ = 0;
  for (std::size_t i = 0; i < kTokenBytes; ++i) differ |= static_cast<std::uint8_t>(a[i] ^ b[i]);
  return differ == 0;
}

}  // namespace l2::viz
