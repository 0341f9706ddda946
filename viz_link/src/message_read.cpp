#include "viz_link/message_read.hpp"

#include <fmt/format.h>

#include "command_line/printable.hpp"

namespace l2::viz {
namespace {

template <class Error>
[[noreturn]] void rethrow_waiting(const Error& e, std::string_view waiting_for) {
  if (waiting_for.empty()) throw e;
  throw Error(fmt::format("{} (waiting for {})", e.what(), waiting_for));
}

}  // namespace

void recv_header(int fd, MessageHead& head, Clock::time_point deadline, const std::string& peer,
                 std::string_view waiting_for) {
  head.clear();
  try {
    recv_all(fd, head.space().data(), kHeaderBytes, deadline, peer);
  } catch (const ConnectionClosed& e) {
    rethrow_waiting(e, waiting_for);
  } catch (const NetError& e) {
    rethrow_waiting(e, waiting_for);
  }
  if (const Status header = head.received(kHeaderBytes); !header.ok()) {
    throw NetError(fmt::format("{}: {}", peer, header.reason()));
  }
}

void recv_fixed(int fd, MessageHead& head, Clock::time_point deadline, const std::string& peer) {
  const std::size_t n = head.space().size();
  recv_all(fd, head.space().data(), n, deadline, peer);
  (void)head.received(n);  // the header is in: the rest of the fixed part cannot fail
}

std::string recv_error_text(int fd, const MessageHead& head, Clock::time_point deadline,
                            const std::string& peer) {
  std::string text(head.header().payload_bytes, '\0');
  recv_all(fd, reinterpret_cast<std::uint8_t*>(text.data()), text.size(), deadline, peer);
  return printable(text);
}

}  // namespace l2::viz
