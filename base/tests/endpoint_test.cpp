// "HOST:PORT" on the command line (--viz, --display-stream): what is taken, and the one line
// that names what is not.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "base/socket.hpp"

namespace l2 {
namespace {

TEST(Endpoint, HostIsEverythingBeforeTheLastColon) {
  const Endpoint v4 = parse_endpoint("127.0.0.1:5000");
  EXPECT_EQ(v4.host, "127.0.0.1");
  EXPECT_EQ(v4.port, 5000);
  const Endpoint v6 = parse_endpoint("::1:65535");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 65535);
  EXPECT_EQ(parse_endpoint("wall-node-3:1").port, 1);
  EXPECT_EQ(endpoint_error("localhost:80"), "");
}

TEST(Endpoint, AnythingButOnePortInRangeIsRefusedByValue) {
  // 99999 and 65536 would wrap to another port in 16 bits; before the check, "h:99999"
  // connected to port 34463 and "h:abc" failed with "stoi".
  for (const char* bad :
       {"127.0.0.1:99999", "127.0.0.1:65536", "127.0.0.1:0", "127.0.0.1:abc", "127.0.0.1:", ":5000",
        "localhost", "127.0.0.1:+80", "127.0.0.1:-80", "127.0.0.1: 80", "127.0.0.1:80x", ""}) {
    const std::string want = std::string("'") + bad + "' is not HOST:PORT (port 1..65535)";
    EXPECT_EQ(endpoint_error(bad), want);
    try {
      parse_endpoint(bad);
      ADD_FAILURE() << bad << " was taken";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), want);
    }
  }
}

}  // namespace
}  // namespace l2
