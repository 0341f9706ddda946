#include "vizserver/display_watcher.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "command_line/printable.hpp"
#include "viz_link/message_read.hpp"

namespace l2::viz {
namespace {

constexpr int kPollSliceMs = 20;  // how soon the reader sees stop_

}  // namespace

Fd accept_within(const Fd& listener, std::chrono::milliseconds timeout) {
  pollfd p{listener.get(), POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return Fd();
  Fd fd(::accept4(listener.get(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC));
  if (fd) set_nodelay(fd.get());
  return fd;
}

Listening read_listening(int fd, Clock::time_point deadline, const std::string& peer) {
  MessageHead head(Protocol::DisplayStream);
  recv_header(fd, head, deadline, peer);
  const Kind kind = head.header().kind;
  if (kind == Kind::Error) {
    throw NetError(fmt::format("{}: {}", peer, recv_error_text(fd, head, deadline, peer)));
  }
  if (kind != Kind::Listening) {
    throw NetError(fmt::format("{}: {} before LISTENING", peer, kind_name(kind)));
  }
  recv_fixed(fd, head, deadline, peer);
  return decode_listening(head.fixed());
}

DisplayWatcher::DisplayWatcher(Fd fd, std::string peer, std::uint32_t display_count,
                               std::size_t max_held, std::chrono::milliseconds io_timeout)
    : fd_(std::move(fd)),
      peer_(std::move(peer)),
      display_count_(display_count),
      max_held_(std::max<std::size_t>(max_held, 1)),
      io_timeout_(io_timeout),
      // The frames held, the one being read and the one its reader still looks at.
      pictures_(PicturePool::make((max_held_ + 2) * display_count)) {
  thread_ = std::thread([this] { run(); });
}

DisplayWatcher::~DisplayWatcher() {
  stop_ = true;
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

FramePtr DisplayWatcher::take(std::uint32_t frame, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  // The caller goes forward: older frames are of no use any more, and would hold room.
  held_.erase(held_.begin(), held_.lower_bound(frame));
  changed_.notify_all();
  changed_.wait_for(lock, timeout, [&] {
    return held_.count(frame) > 0 || ended_ || (last_arrived_ && *last_arrived_ >= frame);
  });
  if (const auto it = held_.find(frame); it != held_.end()) {
    FramePtr f = it->second;
    held_.erase(held_.begin(), std::next(it));
    changed_.notify_all();
    return f;
  }
  if (last_arrived_ && *last_arrived_ >= frame) {
    throw NetError(fmt::format("{}: frame {} is not in the stream (it went on to frame {})", peer_,
                               frame, *last_arrived_));
  }
  if (ended_) throw NetError(*ended_);
  return nullptr;
}

Status DisplayWatcher::ended() const {
  std::lock_guard lock(mutex_);
  if (ended_) return Failure{*ended_};
  return {};
}

bool DisplayWatcher::ended_with_error_message() const {
  std::lock_guard lock(mutex_);
  return error_message_;
}

void DisplayWatcher::run() {
  try {
    read_stream();
  } catch (const std::exception& e) {
    finish(e.what(), false);
  }
}

bool DisplayWatcher::read_exact(std::uint8_t* data, std::size_t n, bool at_boundary,
                                const char* what) {
  const auto deadline = Clock::now() + io_timeout_;
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::recv(fd_.get(), data + got, n - got, 0);
    if (r > 0) {
      got += static_cast<std::size_t>(r);
      continue;
    }
    if (r < 0 && errno == EINTR) continue;
    const bool closed = r == 0 || errno == ECONNRESET;
    if (closed && at_boundary && got == 0) return false;
    if (closed) {
      throw NetError(
          fmt::format("{} closed the connection in the middle of a {} message", peer_, what));
    }
    if (errno != EAGAIN && errno != EWOULDBLOCK) {
      throw NetError(fmt::format("{}: receive failed: {}", peer_, std::strerror(errno)));
    }
    // Between messages the server may be quiet as long as it likes (the run judges stalls);
    // inside a message the rest must follow within io_timeout.
    if ((!at_boundary || got > 0) && Clock::now() > deadline) {
      throw NetError(fmt::format("{}: the rest of a {} message did not arrive within {} ms", peer_,
                                 what, io_timeout_.count()));
    }
    pollfd p{fd_.get(), POLLIN, 0};
    ::poll(&p, 1, kPollSliceMs);
    if (stop_) return false;
  }
  return true;
}

void DisplayWatcher::read_stream() {
  ComposedFrame building;
  bool open = false;  // DISPLAYs of `building` arrived, its SHOWN not yet
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return held_.size() < max_held_ || stop_; });
    }
    MessageHead head(Protocol::DisplayStream);
    if (!read_exact(head.space().data(), kHeaderBytes, true, "message")) {
      if (stop_) return finish(fmt::format("{}: no longer watched", peer_), false);
      return finish(open ? fmt::format("{} closed the connection in the middle of frame {} ({} "
                                       "displays sent, no SHOWN)",
                                       peer_, building.frame, building.displays.size())
                         : fmt::format("{} closed the connection", peer_),
                    false);
    }
    if (const Status header = head.received(kHeaderBytes); !header.ok()) {
      throw NetError(fmt::format("{}: {}", peer_, header.reason()));
    }
    const Header h = head.header();
    const std::size_t fixed = head.space().size();
    if (!read_exact(head.space().data(), fixed, false, kind_name(h.kind))) return;
    (void)head.received(fixed);
    const std::span<const std::uint8_t> fixed_part = head.fixed();
    if (h.kind == Kind::Error) {
      std::string text(h.payload_bytes, '\0');
      if (!read_exact(reinterpret_cast<std::uint8_t*>(text.data()), text.size(), false, "ERROR"))
        return;
      return finish(printable(text), true);
    }
    if (h.kind == Kind::Display) {
      const DisplayHeader d = decode_display(fixed_part);
      if (const Status display = validate(d, h.payload_bytes); !display.ok()) {
        throw NetError(peer_ + ": " + display.reason());
      }
      if (!open) {
        if (last_arrived_ && d.frame <= *last_arrived_) {
          throw NetError(
              fmt::format("{}: frame {} after frame {}", peer_, d.frame, *last_arrived_));
        }
        building = ComposedFrame{};
        building.frame = d.frame;
        open = true;
      }
      if (d.display >= display_count_) {
        throw NetError(
            fmt::format("{}: DISPLAY {} of frame {}, but the stream announced {} displays", peer_,
                        d.display, d.frame, display_count_));
      }
      if (d.frame != building.frame || d.display != building.displays.size()) {
        throw NetError(
            fmt::format("{}: DISPLAY {} of frame {} where display {} of frame {} was due", peer_,
                        d.display, d.frame, building.displays.size(), building.frame));
      }
      RgbImage image = pictures_->take(static_cast<int>(d.width), static_cast<int>(d.height));
      if (!read_exact(image.data(), d.pixel_bytes(), false, "DISPLAY")) return;
      building.displays.push_back(std::move(image));
    } else if (h.kind == Kind::Shown) {
      const Shown s = decode_shown(fixed_part);
      if (!open || s.frame != building.frame || s.display_count != building.displays.size()) {
        throw NetError(fmt::format(
            "{}: SHOWN for frame {} with {} displays, but {} displays of "
            "frame {} arrived",
            peer_, s.frame, s.display_count, open ? building.displays.size() : 0, building.frame));
      }
      building.tiles = s.tiles;
      building.counts.clips = s.clipped_rows;
      building.counts.missing_display = s.missing_display_rows;
      publish(std::move(building));
      open = false;
    } else {
      throw NetError(fmt::format("{}: a second {}", peer_, kind_name(h.kind)));
    }
  }
}

void DisplayWatcher::send_lost(std::uint32_t pipeserver) {
  // The reader thread only reads this socket: a send from here does not meet it.
  const auto message = encode_lost(pipeserver);
  const iovec parts[] = {{const_cast<std::uint8_t*>(message.data()), message.size()}};
  send_all(fd_.get(), parts, Clock::now() + io_timeout_, peer_);
}

void DisplayWatcher::publish(ComposedFrame frame) {
  const std::uint32_t number = frame.frame;
  FramePtr ptr = pictures_->share(std::move(frame));
  {
    std::lock_guard lock(mutex_);
    held_[number] = std::move(ptr);
    last_arrived_ = number;
  }
  changed_.notify_all();
}

void DisplayWatcher::finish(std::string reason, bool error_message) {
  {
    std::lock_guard lock(mutex_);
    if (!ended_) {
      ended_ = std::move(reason);
      error_message_ = error_message;
    }
  }
  changed_.notify_all();
}

}  // namespace l2::viz
