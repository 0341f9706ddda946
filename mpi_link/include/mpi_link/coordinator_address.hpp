// Where the other ranks of an MPI run reach the coordinator beside MPI (its liveness listener,
// mpi_session.hpp). A host name is no answer: on most machines /etc/hosts maps the machine's own
// name to a loopback address, which is another machine's loopback seen from anywhere else. So
// the coordinator offers the addresses of its own interfaces, only those MPI is pinned to when
// it is (`--mca oob_tcp_if_include` / `btl_tcp_if_include`, names or CIDR blocks), and a rank on
// the coordinator's own network stack takes loopback instead.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

struct InterfaceAddress {
  std::string name;        // "eth0"
  std::uint32_t ipv4 = 0;  // host byte order
  bool loopback = false;
};

// Pure: of `interfaces`, those a rank on another host may reach, in order: never loopback;
// with `pin` (a comma-separated list of interface names and a.b.c.d/n blocks, as Open MPI's
// if_include takes them) only the interfaces it names. A malformed entry matches nothing.
std::vector<std::uint32_t> offered_addresses(const std::vector<InterfaceAddress>& interfaces,
                                             std::string_view pin);

std::string ipv4_text(std::uint32_t ipv4);

// The edges: this machine's up IPv4 interfaces (getifaddrs); MPI's pin from the environment
// mpirun gives every rank (OMPI_MCA_oob_tcp_if_include, else btl_tcp_if_include), or empty; and
// which network stack this process is on (boot id and network namespace: two ranks print the
// same only when loopback joins them).
std::vector<InterfaceAddress> local_interfaces();
std::string mpi_interface_pin();
std::string network_stack_id();

}  // namespace l2
