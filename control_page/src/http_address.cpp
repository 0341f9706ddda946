#include "control_page/http_address.hpp"

#include <fmt/format.h>

#include <charconv>

namespace l2 {
namespace {

Result<int> parse_port(std::string_view text) {
  int port = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), port);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || port < 0 ||
      port > 65535)
    return Failure{fmt::format("'{}' is not a port 0..65535", text)};
  return port;
}

}  // namespace

bool HttpAddress::loopback() const {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

Result<HttpAddress> parse_http_address(std::string_view text) {
  HttpAddress a;
  std::string_view port = text;
  if (!text.empty() && text.front() == '[') {  // [IPv6]:PORT
    const auto close = text.find("]:");
    if (close == std::string_view::npos)
      return Failure{fmt::format("'{}': expected [ADDRESS]:PORT for an IPv6 address", text)};
    a.host = std::string(text.substr(1, close - 1));
    port = text.substr(close + 2);
  } else if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    a.host = std::string(text.substr(0, colon));
    port = text.substr(colon + 1);
  }
  if (a.host.empty()) return Failure{fmt::format("'{}': the address before ':' is empty", text)};
  const Result<int> p = parse_port(port);
  if (!p.ok()) return Failure{p.reason()};
  a.port = *p;
  return a;
}

}  // namespace l2
