#include "mpi_link/coordinator_address.hpp"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>

namespace l2 {
namespace {

// "a.b.c.d/n" as (network, mask), or nullopt.
std::optional<std::pair<std::uint32_t, std::uint32_t>> parse_block(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const std::string address(text.substr(0, slash));
  in_addr a{};
  if (inet_pton(AF_INET, address.c_str(), &a) != 1) return std::nullopt;
  const std::string_view bits_text = text.substr(slash + 1);
  int bits = -1;
  const auto [end, ec] =
      std::from_chars(bits_text.data(), bits_text.data() + bits_text.size(), bits);
  if (ec != std::errc{} || end != bits_text.data() + bits_text.size() || bits < 0 || bits > 32)
    return std::nullopt;
  const std::uint32_t mask = bits == 0 ? 0 : ~std::uint32_t{0} << (32 - bits);
  return std::pair{ntohl(a.s_addr) & mask, mask};
}

bool pinned(const InterfaceAddress& i, std::string_view pin) {
  // Its comma-separated entries (not std::views::split: clang 14, the sanitizer builds' compiler,
  // cannot compile libstdc++ 12's views).
  for (std::size_t at = 0; at <= pin.size();) {
    const std::size_t comma = std::min(pin.find(',', at), pin.size());
    const std::string_view entry = pin.substr(at, comma - at);
    at = comma + 1;
    if (entry == i.name) return true;
    if (const auto block = parse_block(entry); block && (i.ipv4 & block->second) == block->first)
      return true;
  }
  return false;
}

std::string first_line(const char* path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

std::vector<std::uint32_t> offered_addresses(const std::vector<InterfaceAddress>& interfaces,
                                             std::string_view pin) {
  std::vector<std::uint32_t> out;
  for (const InterfaceAddress& i : interfaces) {
    if (i.loopback || (!pin.empty() && !pinned(i, pin))) continue;
    out.push_back(i.ipv4);
  }
  return out;
}

std::string ipv4_text(std::uint32_t ipv4) {
  return fmt::format("{}.{}.{}.{}", ipv4 >> 24, (ipv4 >> 16) & 255, (ipv4 >> 8) & 255, ipv4 & 255);
}

std::vector<InterfaceAddress> local_interfaces() {
  std::vector<InterfaceAddress> out;
  ifaddrs* all = nullptr;
  if (getifaddrs(&all) != 0) return out;
  for (const ifaddrs* i = all; i; i = i->ifa_next) {
    if (!i->ifa_addr || i->ifa_addr->sa_family != AF_INET || !(i->ifa_flags & IFF_UP)) continue;
    const auto* in = reinterpret_cast<const sockaddr_in*>(i->ifa_addr);
    out.push_back({i->ifa_name, ntohl(in->sin_addr.s_addr), (i->ifa_flags & IFF_LOOPBACK) != 0});
  }
  freeifaddrs(all);
  return out;
}

std::string mpi_interface_pin() {
  for (const char* name : {"OMPI_MCA_oob_tcp_if_include", "OMPI_MCA_btl_tcp_if_include"})
    if (const char* v = std::getenv(name); v && *v) return v;
  return {};
}

std::string network_stack_id() {
  struct stat net {};
  const std::string boot = first_line("/proc/sys/kernel/random/boot_id");
  if (stat("/proc/self/ns/net", &net) != 0) return boot;
  return fmt::format("{}/{}:{}", boot, net.st_dev, net.st_ino);
}

}  // namespace l2
