// cpp-httplib's server with its connections bounded, in all and per client, and in time. It owns
// the threads that serve connections, which connections they serve, and each one's life.
//
// cpp-httplib 0.11 hands every accepted connection to its task queue, which its ThreadPool keeps
// unbounded, and serves a connection as long as the client sends a byte per read timeout: 500
// idle connections queue in front of the page's next request, and a client sending a byte a
// second keeps a thread for good. Its accepted socket is seen only inside the closure it queues,
// which calls the server's (virtual) process_and_close_socket; so the queue here runs that
// closure at once, on the accepting thread, and this class's process_and_close_socket admits
// the connection or refuses it there, knowing its peer:
//
// - admitted: at most `threads` connections in all, `per_client` from one address, each served
//   by a thread of its own (none waits for one);
// - refused: `503` with `Connection: close`, written without waiting, and closed, so a flood costs
//   the accepting thread a few system calls per connection and holds nothing;
// - in time: a connection waits for its next request at most the keep-alive timeout, a request
//   is read whole within `read_limit` of its first byte and its answer written within
//   `write_limit`, whatever the client trickles.
//
// Served connections run cpp-httplib's own request handling (process_request), so routes,
// limits and answers are the library's. Per client means per address: behind one NAT, or all
// through one SSH tunnel, clients share theirs.
#pragma once

#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace l2 {

struct ConnectionLimits {
  // A browser opens up to 6 connections to a host: one client's share leaves it and a script
  // room, and the total two such clients. A thread waiting on a client costs no CPU.
  int threads = 16;
  int per_client = 8;
  // A request is at most a few KiB (headers, a body of a mode name): seconds are plenty. An
  // answer may be a full-size display's PNG of some MiB, on a slow link.
  std::chrono::milliseconds read_limit{5000};
  std::chrono::milliseconds write_limit{30000};
};

class BoundedServer : public httplib::Server {
 public:
  explicit BoundedServer(const ConnectionLimits& limits);
  ~BoundedServer() override;
  BoundedServer(const BoundedServer&) = delete;
  BoundedServer& operator=(const BoundedServer&) = delete;

  // Call once bound: lets the kernel hold more connections before they are accepted.
  // cpp-httplib listens with a backlog of 5 (CPPHTTPLIB_LISTEN_BACKLOG, fixed in Debian's
  // build): under a flood the kernel then drops connections it has completed, and each comes
  // back only when its handshake is retried (1, 3, 7 s on), the page's own among them. Waiting
  // there holds no thread; the accepting thread drains it quickly, admitting or refusing.
  void deepen_backlog();

  // A POST route whose handler reads the body as it comes. Its reader is cpp-httplib's, with the
  // connection's rules kept whatever the handler does:
  // - a request with neither a length nor chunks has an empty body (HTTP/1.1; cpp-httplib would
  //   read to the connection's end, which a client waiting for its answer never closes);
  // - a body the handler leaves unread (a request refused before its body) is read and dropped
  //   once the handler returns: left on a keep-alive connection, its bytes would be taken for
  //   the client's next request there, which cpp-httplib then answers 400 with nothing in it.
  void post_reading_body(const std::string& pattern, HandlerWithContentReader handler);

  // Ends serving once stop() has ended listening: connections being served end at once (their
  // sockets shut down), those admitted and not yet served are closed, the threads are joined.
  // Handlers run no more after it, so what they use may go. The destructor calls it too.
  void finish();

 private:
  struct Admitted {
    socket_t sock = INVALID_SOCKET;
    std::string client;
  };

  bool process_and_close_socket(socket_t sock) override;
  void work();
  void serve(socket_t sock);
  void done(const Admitted& c);

  const ConnectionLimits limits_;
  std::mutex mutex_;
  std::condition_variable admitted_one_;
  std::deque<Admitted> waiting_;
  std::map<std::string, int> per_client_;  // connections admitted and not yet done, by address
  int admitted_ = 0;
  std::set<socket_t> serving_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace l2
