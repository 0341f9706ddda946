#include "display_sender.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <fmt/format.h>

#include <array>
#include <span>
#include <vector>

namespace l2::viz {
namespace {

iovec part(const void* p, std::size_t n) {
  return {const_cast<void*>(p), n};
}

}  // namespace

DisplaySender DisplaySender::connect(const std::string& host, std::uint16_t port,
                                     std::chrono::milliseconds io_timeout) {
  // The watcher (l2wall run) listens; a vizserver that cannot reach it says so by that name.
  Fd fd = connect_tcp(host, port, std::chrono::seconds(5), "the display stream's watcher");
  return DisplaySender(std::move(fd), fmt::format("display stream {}:{}", host, port), io_timeout);
}

void DisplaySender::send_listening(const Listening& listening) {
  const auto message = encode(listening);
  const iovec parts[] = {part(message.data(), message.size())};
  send_all(fd_.get(), parts, Clock::now() + io_timeout_, peer_);
}

void DisplaySender::send_frame(const ComposedFrame& f) {
  std::vector<std::array<std::uint8_t, kHeaderBytes + 16>> heads;
  heads.reserve(f.displays.size());
  std::vector<iovec> parts;
  for (std::size_t d = 0; d < f.displays.size(); ++d) {
    const RgbImage& image = f.displays[d];
    heads.push_back(encode(DisplayHeader{f.frame, static_cast<std::uint32_t>(d),
                                         static_cast<std::uint32_t>(image.width()),
                                         static_cast<std::uint32_t>(image.height())}));
    parts.push_back(part(heads.back().data(), heads.back().size()));
    parts.push_back(part(image.data(), image.bytes().size()));
  }
  const auto shown =
      encode(Shown{f.frame, static_cast<std::uint32_t>(f.displays.size()),
                   static_cast<std::uint32_t>(f.tiles), static_cast<std::uint32_t>(f.counts.clips),
                   static_cast<std::uint32_t>(f.counts.missing_display)});
  parts.push_back(part(shown.data(), shown.size()));
  send_all(fd_.get(), parts, Clock::now() + io_timeout_, peer_);
}

void DisplaySender::send_error(const std::string& text) noexcept {
  try {
    const std::string body = text.substr(0, kMaxErrorText);
    const auto head = encode_error_header(body.size());
    const iovec parts[] = {part(head.data(), head.size()), part(body.data(), body.size())};
    send_all(fd_.get(), parts, Clock::now() + std::chrono::seconds(1), peer_);
  } catch (const std::exception&) {
    // The watcher is gone or not reading: it will see the connection close instead.
  }
}

std::vector<std::uint32_t> DisplaySender::take_lost() {
  std::vector<std::uint32_t> lost;
  for (;;) {
    std::array<std::uint8_t, kHeaderBytes + 4> m{};
    const ssize_t n = ::recv(fd_.get(), m.data(), m.size(), MSG_PEEK | MSG_DONTWAIT);
    // Nothing yet, EOF (watcher_gone() says so), or a message not all here: later.
    if (n < static_cast<ssize_t>(m.size())) return lost;
    const Result<Header> h =
        decode_header(std::span<const std::uint8_t, kHeaderBytes>(m.data(), kHeaderBytes),
                      Protocol::DisplayStream);
    if (!h.ok() || h->kind != Kind::Lost || h->payload_bytes != 4) {
      throw NetError(fmt::format("{}: the watcher sent {} where only LOST may come", peer_,
                                 h.ok() ? kind_name(h->kind) : h.reason()));
    }
    [[maybe_unused]] const ssize_t taken = ::recv(fd_.get(), m.data(), m.size(), MSG_DONTWAIT);
    lost.push_back(get_u32(m.data() + kHeaderBytes));
  }
}

bool DisplaySender::watcher_gone() const {
  pollfd p{fd_.get(), POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  char byte = 0;
  return ::recv(fd_.get(), &byte, 1, MSG_PEEK | MSG_DONTWAIT) <= 0 || (p.revents & POLLHUP);
}

}  // namespace l2::viz
