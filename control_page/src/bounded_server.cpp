#include "bounded_server.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <string_view>

#include <fmt/format.h>

#include "base/socket.hpp"
#include "connection_stream.hpp"

namespace l2 {

namespace {

// cpp-httplib's queue for accepted connections: runs each at once, on the accepting thread,
// where BoundedServer::process_and_close_socket admits or refuses it without waiting.
class AdmitAtOnce final : public httplib::TaskQueue {
 public:
  void enqueue(std::function<void()> fn) override { fn(); }
  void shutdown() override {}
};

// The answer to a connection over the bounds. Sent without waiting (a new connection's send
// buffer is empty), the request unread: the client may see the connection reset instead.
void refuse(socket_t sock) {
  static const std::string busy = [] {
    const std::string_view body = R"({"error":"too many connections: close some, then ask again"})";
    return fmt::format(
        "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
        "Content-Length: {}\r\nConnection: close\r\nRetry-After: 1\r\n\r\n{}",
        body.size(), body);
  }();
  [[maybe_unused]] const ssize_t sent =
      ::send(sock, busy.data(), busy.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

template <class Rep>
std::chrono::microseconds seconds_and_us(Rep sec, Rep usec) {
  return std::chrono::seconds(sec) + std::chrono::microseconds(usec);
}

}  // namespace

BoundedServer::BoundedServer(const ConnectionLimits& limits) : limits_(limits) {
  new_task_queue = [] { return new AdmitAtOnce; };
  for (int i = 0; i < limits_.threads; ++i) threads_.emplace_back([this] { work(); });
}

BoundedServer::~BoundedServer() {
  finish();
}

void BoundedServer::finish() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    for (const socket_t sock : serving_) ::shutdown(sock, SHUT_RDWR);
  }
  admitted_one_.notify_all();
  for (std::thread& t : threads_) t.join();
  threads_.clear();
}

void BoundedServer::deepen_backlog() {
  // The kernel caps it at net.core.somaxconn.
  constexpr int kBacklog = 1024;
  ::listen(svr_sock_, kBacklog);
}

void BoundedServer::post_reading_body(const std::string& pattern,
                                      HandlerWithContentReader handler) {
  Post(pattern, [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res,
                                               const httplib::ContentReader& body) {
    const bool has_body = req.has_header("Content-Length") || req.has_header("Transfer-Encoding");
    bool asked = false;
    const httplib::ContentReader reader(
        [&](httplib::ContentReceiver receive) {
          asked = true;
          return !has_body || body(std::move(receive));
        },
        [&](httplib::MultipartContentHeader header, httplib::ContentReceiver receive) {
          asked = true;
          return !has_body || body(std::move(header), std::move(receive));
        });
    handler(req, res, reader);
    if (has_body && !asked) (void)body([](const char*, std::size_t) { return true; });
  });
}

// On the accepting thread: admitted to a thread of its own, or refused; never waits.
bool BoundedServer::process_and_close_socket(socket_t sock) {
  std::string client = peer_address(sock).host;
  {
    const std::lock_guard lock(mutex_);
    int& from_client = per_client_[client];
    if (!stopping_ && admitted_ < limits_.threads && from_client < limits_.per_client) {
      ++admitted_;
      ++from_client;
      waiting_.push_back({sock, std::move(client)});
      admitted_one_.notify_one();
      return true;
    }
    if (from_client == 0) per_client_.erase(client);
  }
  refuse(sock);
  return false;
}

void BoundedServer::work() {
  for (;;) {
    Admitted c;
    bool serve_it = false;
    {
      std::unique_lock lock(mutex_);
      admitted_one_.wait(lock, [&] { return stopping_ || !waiting_.empty(); });
      if (waiting_.empty()) return;
      c = std::move(waiting_.front());
      waiting_.pop_front();
      serve_it = !stopping_;
      if (serve_it) serving_.insert(c.sock);
    }
    if (serve_it) serve(c.sock);
    done(c);
  }
}

// cpp-httplib's keep-alive loop, with ConnectionStream's deadlines on each request.
void BoundedServer::serve(socket_t sock) {
  ConnectionStream stream(sock, seconds_and_us(read_timeout_sec_, read_timeout_usec_),
                          seconds_and_us(write_timeout_sec_, write_timeout_usec_));
  for (std::size_t left = keep_alive_max_count_; left > 0; --left) {
    if (!stream.next_request(std::chrono::seconds(keep_alive_timeout_sec_), limits_.read_limit,
                             limits_.write_limit))
      return;
    bool closed = false;
    const bool last = left == 1;
    if (!process_request(stream, last, closed, nullptr) || closed) return;
  }
}

void BoundedServer::done(const Admitted& c) {
  {
    const std::lock_guard lock(mutex_);
    serving_.erase(c.sock);
    --admitted_;
    if (--per_client_[c.client] == 0) per_client_.erase(c.client);
  }
  ::shutdown(c.sock, SHUT_RDWR);
  ::close(c.sock);
}

}  // namespace l2
