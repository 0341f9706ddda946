// The control page's server under a flood of connections, with real sockets on loopback: idle
// connections by the hundred and clients sending a byte at a time neither stop it answering
// others nor stay; what it holds stays bounded. The flood comes from other loopback addresses
// (all of 127.0.0.0/8 is this machine), as from other machines: the bounds are per address.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "base/fd.hpp"
#include "bounded_server.hpp"
#include "control_page/control_server.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr const char* kFloodToken = "0123456789abcdef0123456789abcdef";
// Far above what each wait takes here (milliseconds to answer, the 2 s keep-alive, the 5 s
// request limit), and far below what an unbounded queue of 500 idle connections would take.
constexpr auto kCeiling = 20s;

HttpAddress loopback() {
  HttpAddress a;
  a.host = "127.0.0.1";
  return a;
}

// A non-blocking TCP connection from `source` (a loopback address) to 127.0.0.1:port, begun.
Fd connect_from(const char* source, int port) {
  Fd fd(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  sockaddr_in a{};
  a.sin_family = AF_INET;
  inet_pton(AF_INET, source, &a.sin_addr);
  EXPECT_EQ(::bind(fd.get(), reinterpret_cast<sockaddr*>(&a), sizeof a), 0) << source;
  inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  ::connect(fd.get(), reinterpret_cast<sockaddr*>(&a), sizeof a);
  return fd;
}

// Waits until `fd`'s connection is made (false: it failed or took past the ceiling).
bool connected(const Fd& fd) {
  pollfd p{fd.get(), POLLOUT, 0};
  if (::poll(&p, 1, static_cast<int>(std::chrono::milliseconds(kCeiling).count())) != 1)
    return false;
  int error = 0;
  socklen_t len = sizeof error;
  ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &error, &len);
  return error == 0;
}

// What the server sent before it closed the connection, once it has; nullopt: still open at
// `until`.
std::optional<std::string> closed_by_server(const Fd& fd, Clock::time_point until) {
  std::string got;
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - Clock::now()).count();
    pollfd p{fd.get(), POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) != 1) return std::nullopt;
    char buf[512];
    const ssize_t n = ::recv(fd.get(), buf, sizeof buf, 0);
    if (n <= 0) return got;  // its end (or a reset)
    got.append(buf, static_cast<std::size_t>(n));
  }
}

// The status GET /api/state gets from 127.0.0.1 (-1: none), and how long it took. It asks the
// server to close the connection and reads to the end: the server has let the connection go
// (and counts it no more) before the end comes, so what follows sees it gone.
std::pair<int, Clock::duration> get_state(int port) {
  const auto start = Clock::now();
  const Fd fd = connect_from("127.0.0.1", port);
  if (!connected(fd)) return {-1, Clock::now() - start};
  const std::string_view request =
      "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
  if (::send(fd.get(), request.data(), request.size(), MSG_NOSIGNAL) !=
      static_cast<ssize_t>(request.size()))
    return {-1, Clock::now() - start};
  const auto answer = closed_by_server(fd, start + kCeiling);
  const auto took = Clock::now() - start;
  if (!answer || !answer->starts_with("HTTP/1.1 ") || answer->size() < 12) return {-1, took};
  return {std::stoi(answer->substr(9, 3)), took};
}

int open_files() {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

int threads() {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

TEST(ConnectionBounds, FiveHundredIdleConnectionsNeitherStopThePageNorStay) {
  ControlServer server(loopback(), kFloodToken);
  server.publish(RunState{});
  ASSERT_EQ(get_state(server.port()).first, 200);
  const int files_before = open_files(), threads_before = threads();

  std::vector<Fd> idle;
  for (int i = 0; i < 500; ++i) idle.push_back(connect_from("127.0.0.2", server.port()));
  for (const Fd& fd : idle) ASSERT_TRUE(connected(fd));
  const auto [status, took] = get_state(server.port());
  EXPECT_EQ(status, 200);
  EXPECT_LT(took, 5s) << "the page waited behind the idle connections";
  // Accepted after the 500 (in order): the server holds a bounded few of theirs, no more threads.
  const int server_files = open_files() - files_before - 500;
  EXPECT_LE(server_files, ConnectionLimits{}.threads) << "sockets the server holds";
  EXPECT_EQ(threads(), threads_before);

  // Those over the bound are answered 503 at once; the rest closed once idle for the keep-alive.
  const auto until = Clock::now() + kCeiling;
  int busy = 0, quiet = 0;
  for (const Fd& fd : idle) {
    const auto said = closed_by_server(fd, until);
    ASSERT_TRUE(said) << "an idle connection stayed open";
    busy += said->starts_with("HTTP/1.1 503 Service Unavailable\r\n");
    quiet += said->empty();
  }
  EXPECT_EQ(busy + quiet, 500);
  EXPECT_LE(quiet, ConnectionLimits{}.per_client) << "served from one address at once";
}

// Sends `text` a byte per `every` until the server closes the connection; the bytes it took.
std::size_t trickle(const Fd& fd, std::string_view text, Clock::duration every) {
  std::size_t sent = 0;
  for (const auto end = Clock::now() + kCeiling; Clock::now() < end && sent < text.size();) {
    if (::send(fd.get(), text.data() + sent, 1, MSG_NOSIGNAL) != 1) break;
    ++sent;
    std::this_thread::sleep_for(every);
    pollfd p{fd.get(), POLLIN, 0};
    if (::poll(&p, 1, 0) == 1) break;  // the server answered or closed
  }
  return sent;
}

// Slow connections from `source`, each sending `request` a byte at a time on a thread of its own
// until the server closes it; `sent` gets the bytes each sent.
struct SlowClients {
  std::vector<Fd> fds;
  std::vector<std::size_t> sent;
  std::vector<std::thread> senders;

  SlowClients(const char* source, int port, int count, const std::string& request)
      : sent(static_cast<std::size_t>(count)) {
    for (int i = 0; i < count; ++i) {
      fds.push_back(connect_from(source, port));
      EXPECT_TRUE(connected(fds.back()));
    }
    for (std::size_t i = 0; i < fds.size(); ++i)
      senders.emplace_back([this, i, &request] { sent[i] = trickle(fds[i], request, 200ms); });
  }
  void join() {
    for (std::thread& t : senders) t.join();
  }
};

TEST(ConnectionBounds, ClientsSendingAByteAtATimeNeitherStopThePageNorStay) {
  ControlServer server(loopback(), kFloodToken);
  server.publish(RunState{});
  const int per_client = ConnectionLimits{}.per_client;
  // A request a byte every 200 ms: some 40 s to send whole, were it let.
  const std::string request =
      "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: " + std::string(150, 'x') + "\r\n\r\n";
  const auto start = Clock::now();
  SlowClients one("127.0.0.3", server.port(), 2 * per_client, request);
  std::this_thread::sleep_for(300ms);
  const auto [status, took] = get_state(server.port());
  EXPECT_EQ(status, 200) << "a slow client's connections took the page from others";
  EXPECT_LT(took, 5s);

  // A second address takes the threads left: a third is refused at once, nothing waits.
  SlowClients two("127.0.0.4", server.port(), per_client, request);
  std::this_thread::sleep_for(300ms);
  const Fd third = connect_from("127.0.0.5", server.port());
  const auto refused = closed_by_server(third, Clock::now() + kCeiling);
  ASSERT_TRUE(refused);
  EXPECT_TRUE(refused->starts_with("HTTP/1.1 503 ")) << *refused;

  // Every slow connection is cut off before its request is whole, well before the ceiling, and
  // closed; the page then answers again.
  one.join();
  two.join();
  for (const auto* clients : {&one, &two}) {
    for (const std::size_t n : clients->sent) EXPECT_LT(n, request.size());
    for (const Fd& fd : clients->fds) EXPECT_TRUE(closed_by_server(fd, start + kCeiling));
  }
  EXPECT_EQ(get_state(server.port()).first, 200);
}

}  // namespace
}  // namespace l2
