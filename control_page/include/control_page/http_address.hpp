// `--http [ADDR:]PORT`: where the control page listens. Without an address it is 127.0.0.1,
// reached from this machine only; port 0 asks the system for a free port (the URL printed at
// start says which).
#pragma once

#include <string>
#include <string_view>

#include "base/result.hpp"

namespace l2 {

struct HttpAddress {
  std::string host = "127.0.0.1";
  int port = 0;
  // Whether only this machine can reach it (127.0.0.0/8, ::1, localhost): reading the page then
  // needs no token, steering still does.
  bool loopback() const;
};

// "8080", "127.0.0.1:8080", "0.0.0.0:8080", "[::1]:8080". The failure says what is wrong with
// `text` ("'80800' is not a port 0..65535").
Result<HttpAddress> parse_http_address(std::string_view text);

}  // namespace l2
