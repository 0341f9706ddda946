// One served connection as cpp-httplib reads and writes it (its Stream), under deadlines: it owns
// the connection's read buffer and the time its current request has left. cpp-httplib's own
// stream waits a read timeout per read, so a client sending a byte a second never runs out; this
// one also ends a request's reading `read_limit` after it began, and its answer's writing
// `write_limit` after that began.
#pragma once

#include <httplib.h>

#include <chrono>
#include <string>

namespace l2 {

class ConnectionStream final : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;

  // `wait`: the longest a single read or write waits for the client (cpp-httplib's timeouts).
  ConnectionStream(socket_t sock, Clock::duration read_wait, Clock::duration write_wait);

  // Waits up to `idle` for the next request's first byte; false: none came (or the client
  // closed). The request then has `read_limit` to arrive and its answer `write_limit` to go.
  bool next_request(Clock::duration idle, Clock::duration read_limit, Clock::duration write_limit);

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return sock_; }

 private:
  bool wait(short events, Clock::duration most) const;

  const socket_t sock_;
  const Clock::duration read_wait_, write_wait_;
  Clock::duration write_limit_{};
  Clock::time_point deadline_{};
  bool writing_ = false;  // the answer has begun: the deadline is the write's
  std::string buffer_;    // read and not yet taken
  std::size_t taken_ = 0;
};

}  // namespace l2
