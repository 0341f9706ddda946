// Which of the coordinator's addresses a rank on another host is offered (pure logic).
#include "mpi_link/coordinator_address.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

constexpr std::uint32_t ip(int a, int b, int c, int d) {
  return static_cast<std::uint32_t>(a) << 24 | static_cast<std::uint32_t>(b) << 16 |
         static_cast<std::uint32_t>(c) << 8 | static_cast<std::uint32_t>(d);
}

const std::vector<InterfaceAddress> kInterfaces = {
    {"lo", ip(127, 0, 0, 1), true},
    {"eth0", ip(192, 168, 1, 20), false},
    {"ib0", ip(10, 40, 0, 7), false},
    {"docker0", ip(172, 17, 0, 1), false},
};

TEST(CoordinatorAddress, WithoutAPinEveryInterfaceButLoopbackInOrder) {
  EXPECT_EQ(offered_addresses(kInterfaces, ""),
            (std::vector<std::uint32_t>{ip(192, 168, 1, 20), ip(10, 40, 0, 7), ip(172, 17, 0, 1)}));
}

TEST(CoordinatorAddress, APinByNameOrBlockKeepsOnlyWhatItNames) {
  EXPECT_EQ(offered_addresses(kInterfaces, "ib0"), (std::vector<std::uint32_t>{ip(10, 40, 0, 7)}));
  EXPECT_EQ(offered_addresses(kInterfaces, "10.40.0.0/16"),
            (std::vector<std::uint32_t>{ip(10, 40, 0, 7)}));
  EXPECT_EQ(offered_addresses(kInterfaces, "192.168.1.0/24,docker0"),
            (std::vector<std::uint32_t>{ip(192, 168, 1, 20), ip(172, 17, 0, 1)}));
  // Loopback is never offered to another host, pinned or not.
  EXPECT_TRUE(offered_addresses(kInterfaces, "lo").empty());
  EXPECT_TRUE(offered_addresses(kInterfaces, "127.0.0.0/8").empty());
}

TEST(CoordinatorAddress, AMalformedPinEntryMatchesNothing) {
  EXPECT_TRUE(offered_addresses(kInterfaces, "10.40.0.0/33").empty());
  EXPECT_TRUE(offered_addresses(kInterfaces, "10.40.0/16").empty());
  EXPECT_TRUE(offered_addresses(kInterfaces, "eth").empty());
  EXPECT_EQ(offered_addresses(kInterfaces, "0.0.0.0/0").size(), 3u);
}

TEST(CoordinatorAddress, Ipv4Text) {
  EXPECT_EQ(ipv4_text(ip(10, 40, 0, 7)), "10.40.0.7");
}

}  // namespace
}  // namespace l2
