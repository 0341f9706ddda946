// Plain POSIX TCP, and UDP for datagrams taken in (descriptors owned by l2::Fd), for every part
// that talks over a network (the compositing server's tile port and display stream, the MPI ranks'
// coordinator address): listen and connect with bounded waits, and send/receive loops that survive
// partial transfers and EINTR. Sockets are non-blocking throughout; "blocking" calls here wait in
// poll() up to a deadline, so no call can hang on a dead or silent peer.
//
//   const Fd listener = listen_tcp("127.0.0.1", 0);            // a free port
//   const Fd fd = connect_tcp("127.0.0.1", local_port(listener.get()), 500ms, "the server");
//   send_all(fd.get(), parts, steady_clock::now() + 1s, peer_name(fd.get()));
#pragma once

#include <sys/uio.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "base/fd.hpp"

namespace l2 {

// Every network failure: one line naming the peer ("compositing server 127.0.0.1:5000: ...").
class NetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The peer closed the connection (end of stream, reset, broken pipe) without a word: the one
// failure a pipeserver answers by connecting again while it is still saying HELLO.
class ConnectionClosed : public NetError {
 public:
  using NetError::NetError;
};

// A TCP address as written on a command line (--viz, --display-stream): "HOST:PORT", the host
// before the last ':' (so "::1:5000" works), the port a number 1..65535 and nothing after it.
struct Endpoint {
  std::string host;
  std::uint16_t port = 0;
};
// Empty when `text` is such an address, else one line saying why not: a command-line check.
std::string endpoint_error(std::string_view text);
// Throws std::invalid_argument with endpoint_error's line.
Endpoint parse_endpoint(std::string_view text);

// Listens on host:port (port 0: the kernel picks a free one; read it with local_port).
Fd listen_tcp(const std::string& host, std::uint16_t port);
// A non-blocking UDP socket bound to host:port (port 0: a free one), for datagrams taken in.
Fd bind_udp(const std::string& host, std::uint16_t port);
std::uint16_t local_port(int fd);
// A socket's end: the host as inet_ntop writes it ("127.0.0.1", "::1") and the port; "?" and 0
// when the socket has none.
struct SocketAddress {
  std::string host;
  std::uint16_t port = 0;
};
SocketAddress peer_address(int fd);
SocketAddress local_address(int fd);
// "127.0.0.1:43210" ("[::1]:43210") for a connected socket.
std::string peer_name(int fd);

// Connects to host:port, retrying refused connections (the server may not be listening yet)
// until `timeout` has passed. The socket is non-blocking with TCP_NODELAY. A failure is a
// NetError "cannot connect to <what> host:port within N ms: <reason>".
Fd connect_tcp(const std::string& host, std::uint16_t port, std::chrono::milliseconds timeout,
               std::string_view what = "server");

void set_nonblocking(int fd);
void set_nodelay(int fd);

// Sends every byte of `parts` (gathered, no copy) before `deadline`. Throws NetError naming
// `peer` on timeout or error; a peer that closed gives "closed the connection".
void send_all(int fd, std::span<const iovec> parts, std::chrono::steady_clock::time_point deadline,
              const std::string& peer);
// Receives exactly n bytes before `deadline`; throws NetError likewise.
void recv_all(int fd, std::uint8_t* data, std::size_t n,
              std::chrono::steady_clock::time_point deadline, const std::string& peer);

}  // namespace l2
