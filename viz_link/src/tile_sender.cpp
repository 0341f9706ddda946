#include "viz_link/tile_sender.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "viz_link/message_read.hpp"

#include "viz_link/wire.hpp"

namespace l2::viz {
namespace {

iovec part(const void* p, std::size_t n) {
  return {const_cast<void*>(p), n};
}

}  // namespace

TileSender::TileSender(Fd fd, std::string peer, int pipeserver_id, SenderOptions options)
    : fd_(std::move(fd)), peer_(std::move(peer)), pipeserver_id_(pipeserver_id), options_(options) {
  if (options_.codec) deltas_.emplace(*options_.codec);
}

TileSender TileSender::connect(const std::string& host, std::uint16_t port, int pipeserver_id,
                               int display_count, SenderOptions options) {
  if (pipeserver_id < 0 || display_count < 0) {
    throw std::invalid_argument("TileSender: negative pipeserver id or display count");
  }
  const auto give_up = Clock::now() + options.connect_timeout;
  const std::string peer = fmt::format("compositing server {}:{}", host, port);
  for (int attempt = 1;; ++attempt) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - Clock::now());
    Fd fd =
        connect_tcp(host, port, std::max(left, std::chrono::milliseconds(1)), "compositing server");
    TileSender s(std::move(fd), peer, pipeserver_id, options);
    if (s.say_hello(display_count)) return s;
    if (Clock::now() >= give_up) {
      throw NetError(fmt::format("{} closed the connection before WELCOME, {} times within {} ms",
                                 peer, attempt, options.connect_timeout.count()));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

bool TileSender::say_hello(int display_count) {
  const auto hello = encode(Hello{static_cast<std::uint32_t>(pipeserver_id_),
                                  static_cast<std::uint32_t>(display_count), options_.token});
  const iovec parts[] = {part(hello.data(), hello.size())};
  const auto deadline = Clock::now() + options_.io_timeout;
  try {
    send(parts);
    while (!welcomed_) read_message(deadline, "WELCOME");
  } catch (const ConnectionClosed&) {
    if (!server_error_.empty()) throw;  // refused, with its reason
    return false;
  }
  return true;
}

void TileSender::send(std::span<const iovec> parts) {
  try {
    send_all(fd_.get(), parts, Clock::now() + options_.io_timeout, peer_);
  } catch (const NetError&) {
    // The server may have said why it closed us before it did: prefer its words.
    try {
      while (server_error_.empty()) {
        read_message(Clock::now() + std::chrono::milliseconds(200), "its reason");
      }
    } catch (const NetError&) {
    }
    if (!server_error_.empty()) throw NetError(fmt::format("{}: {}", peer_, server_error_));
    throw;
  }
}

void TileSender::send_tile(std::uint32_t frame, const TileTarget& t, const std::uint8_t* rgb,
                           std::size_t stride) {
  if (t.w < 1 || t.w > kMaxTileSide || t.h < 1 || t.h > kMaxTileSide || t.display < 0) {
    throw std::invalid_argument(
        fmt::format("send_tile: tile {}x{} on display {}: sides must "
                    "be 1..{}",
                    t.w, t.h, t.display, kMaxTileSide));
  }
  const TileHeader h{frame,
                     static_cast<std::uint32_t>(t.display),
                     t.x,
                     t.y,
                     static_cast<std::uint32_t>(t.w),
                     static_cast<std::uint32_t>(t.h),
                     t.how,
                     t.key};
  if (const Status tile = validate(h, static_cast<std::uint32_t>(h.fixed_size() + h.pixel_bytes()));
      !tile.ok()) {
    throw std::invalid_argument("send_tile: " + tile.reason());
  }
  if (deltas_) {
    const std::span<const std::uint8_t> encoded = deltas_->encode(h, rgb, stride);
    const auto head = encode_delta(h, encoded.size());
    const iovec parts[] = {part(head.data(), head.size()), part(encoded.data(), encoded.size())};
    send(parts);
    return;
  }
  const auto head = encode(h);
  const auto head_ext = encode_ext(h);
  const std::size_t row_bytes = h.row_bytes();
  std::vector<iovec> parts;
  if (h.how == TileKind::Copy) {
    parts.push_back(part(head.data(), head.size()));
  } else {
    parts.push_back(part(head_ext.data(), head_ext.size()));
  }
  if (stride == row_bytes) {
    parts.push_back(part(rgb, row_bytes * static_cast<std::size_t>(t.h)));
  } else {
    parts.reserve(1 + static_cast<std::size_t>(t.h));
    for (int r = 0; r < t.h; ++r) parts.push_back(part(rgb + r * stride, row_bytes));
  }
  send(parts);
}

void TileSender::finish_frame(std::uint32_t frame, std::uint32_t tiles_sent) {
  if (deltas_) deltas_->end_frame();
  const auto msg = encode(FrameDone{static_cast<std::uint32_t>(pipeserver_id_), frame, tiles_sent});
  const iovec parts[] = {part(msg.data(), msg.size())};
  send(parts);
}

void TileSender::wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  const std::string what = fmt::format("SWAPPED for frame {}", frame);
  while (!last_swapped_ || *last_swapped_ < frame) read_message(deadline, what.c_str());
}

void TileSender::read_message(Clock::time_point deadline, const char* waiting_for) {
  MessageHead head(Protocol::Tiles);
  recv_header(fd_.get(), head, deadline, peer_, waiting_for);
  const Header& header = head.header();
  if (header.kind == Kind::Error) {
    server_error_ = recv_error_text(fd_.get(), head, deadline, peer_);
    throw NetError(fmt::format("{}: {}", peer_, server_error_));
  }
  recv_fixed(fd_.get(), head, deadline, peer_);
  const std::span<const std::uint8_t> body = head.fixed();
  if (header.kind == Kind::Swapped) {
    last_swapped_ = decode_swapped(body).frame;
  } else if (header.kind == Kind::Welcome && !welcomed_) {
    welcomed_ = true;
  } else {
    throw NetError(fmt::format("{}: unexpected {} message", peer_, kind_name(header.kind)));
  }
}

}  // namespace l2::viz
