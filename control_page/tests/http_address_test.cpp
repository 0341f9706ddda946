#include "control_page/http_address.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(HttpAddress, APortAloneListensOnThisMachineOnly) {
  const Result<HttpAddress> a = parse_http_address("8080");
  ASSERT_TRUE(a.ok()) << a.reason();
  EXPECT_EQ(a->host, "127.0.0.1");
  EXPECT_EQ(a->port, 8080);
  EXPECT_TRUE(a->loopback());
}

TEST(HttpAddress, AddressAndPort) {
  const Result<HttpAddress> a = parse_http_address("0.0.0.0:0");
  ASSERT_TRUE(a.ok()) << a.reason();
  EXPECT_EQ(a->host, "0.0.0.0");
  EXPECT_EQ(a->port, 0);
  EXPECT_FALSE(a->loopback());
  const Result<HttpAddress> v6 = parse_http_address("[::1]:9000");
  ASSERT_TRUE(v6.ok()) << v6.reason();
  EXPECT_EQ(v6->host, "::1");
  EXPECT_EQ(v6->port, 9000);
  EXPECT_TRUE(v6->loopback());
  EXPECT_TRUE(parse_http_address("127.0.0.2:1")->loopback());
  EXPECT_FALSE(parse_http_address("192.0.2.1:1")->loopback());
}

TEST(HttpAddress, MistakesAreNamed) {
  EXPECT_EQ(parse_http_address("80800").reason(), "'80800' is not a port 0..65535");
  EXPECT_EQ(parse_http_address("host:").reason(), "'' is not a port 0..65535");
  EXPECT_EQ(parse_http_address(":80").reason(), "':80': the address before ':' is empty");
  EXPECT_EQ(parse_http_address("[::1]80").reason(),
            "'[::1]80': expected [ADDRESS]:PORT for an IPv6 address");
  EXPECT_EQ(parse_http_address("8o").reason(), "'8o' is not a port 0..65535");
}

}  // namespace
}  // namespace l2
