#include "server_loop.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string_view>

#include "command_line/printable.hpp"
#include "vizserver/picture_pool.hpp"

namespace l2::viz {
namespace {

constexpr int kTickMs = 50;                    // timers are checked at least this often
constexpr std::size_t kReadBudget = 8u << 20;  // per connection per round: fairness
// Connections that have not said HELLO, at most, so that a flood of strangers cannot take every
// descriptor (after which accept() fails while the listener stays readable, and the loop would
// spin). The oldest gives way to a new one: a pipeserver says HELLO as soon as it connects.
constexpr std::size_t kMaxStrangers = 16;

double seconds(std::chrono::milliseconds ms) {
  return static_cast<double>(ms.count()) / 1000.0;
}

}  // namespace

ServerLoop::ServerLoop(const ServerOptions& options, Fd listener, std::uint16_t port,
                       std::shared_ptr<ServerShared> shared,
                       std::function<void(const FramePtr&)> on_swap)
    : options_(options),
      listener_(std::move(listener)),
      port_(port),
      shared_(std::move(shared)),
      on_swap_(std::move(on_swap)),
      assembler_(options.display_sizes, options.pipeservers, options.background,
                 options.max_buffered_bytes) {
  if (options.survive_losses) assembler_.survive_losses();
  int fds[2];
  if (::pipe2(fds, O_NONBLOCK | O_CLOEXEC) != 0) {
    throw NetError(fmt::format("vizserver: pipe failed: {}", std::strerror(errno)));
  }
  wake_read_ = Fd(fds[0]);
  wake_write_ = Fd(fds[1]);
  started_ = Clock::now();
  thread_ = std::thread([this] { run(); });
}

ServerLoop::~ServerLoop() {
  stop();
  if (thread_.joinable()) thread_.join();
}

void ServerLoop::stop() {
  {
    std::lock_guard lock(shared_->mutex);
    shared_->stop = true;
  }
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(wake_write_.get(), &byte, 1);
}

void ServerLoop::lose(int pipeserver) {
  {
    std::lock_guard lock(shared_->mutex);
    shared_->lose.push_back(pipeserver);
  }
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(wake_write_.get(), &byte, 1);
}

bool ServerLoop::woken() {
  char scratch[64];
  while (::read(wake_read_.get(), scratch, sizeof scratch) > 0) {
  }
  std::vector<int> lose;
  {
    std::lock_guard lock(shared_->mutex);
    if (shared_->stop) return true;
    lose.swap(shared_->lose);
  }
  for (const int s : lose) {
    if (const Status taken = assembler_.lose(s); !taken.ok()) {
      log_error(fmt::format("LOST from the watcher: {}", taken.reason()));
      continue;
    }
    bool connected = false;
    for (auto& c : conns_) {
      if (c->dead || c->pipeserver != s) continue;
      connected = true;
      close(*c, std::nullopt);
    }
    if (!connected && !assembler_.connected(s)) ++lost_before_hello_;
    log_error(fmt::format("pipeserver {} lost: the run goes on without it", s));
  }
  return false;
}

void ServerLoop::peer_closed(Connection& c, std::optional<std::string> reason) {
  if (options_.survive_losses && c.pipeserver >= 0) {
    // Noted when it leaves work behind; one that ends after its last frame leaves none.
    if (reason || assembler_.frame_waiting_for(c.pipeserver)) {
      log_error(reason.value_or(
          fmt::format("{} closed the connection while a frame waits for it", who(c))));
    }
    reason.reset();
  }
  close(c, reason);
}

void ServerLoop::run() {
  std::vector<pollfd> fds;
  for (;;) {
    fds.clear();
    fds.push_back({wake_read_.get(), POLLIN, 0});
    fds.push_back({listener_.get(), POLLIN, 0});
    for (const auto& c : conns_) {
      const short events = static_cast<short>(POLLIN | (c->out_sent < c->out.size() ? POLLOUT : 0));
      fds.push_back({c->fd.get(), events, 0});
    }
    const int rc = ::poll(fds.data(), fds.size(), kTickMs);
    if (rc < 0 && errno != EINTR) {
      fail(fmt::format("vizserver: poll failed: {}", std::strerror(errno)));
    }
    if (rc > 0 && (fds[0].revents & POLLIN) && woken()) break;  // stop()
    if (rc > 0 && (fds[1].revents & POLLIN)) accept_all();
    // conns_ may have grown in accept_all; only the ones polled have revents.
    for (std::size_t i = 2; i < fds.size() && !failure_; ++i) {
      Connection& c = *conns_[i - 2];
      const short ev = fds[i].revents;
      if (!c.dead && (ev & POLLOUT)) flush(c);
      if (!c.dead && (ev & (POLLIN | POLLHUP | POLLERR))) read_some(c);
    }
    if (!failure_) publish_swaps();
    if (!failure_) check_timers(Clock::now());
    std::erase_if(conns_, [](const auto& c) { return c->dead; });
    if (failure_) break;
    if (assembler_.all_done()) {
      std::lock_guard lock(shared_->mutex);
      shared_->all_left = true;
      break;
    }
  }
  shut_down();
}

void ServerLoop::accept_all() {
  for (;;) {
    Fd fd(::accept4(listener_.get(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC));
    if (!fd) {
      if (errno == EINTR) continue;
      return;  // EAGAIN, or a connection that vanished before we took it
    }
    make_room_for_a_stranger();
    set_nodelay(fd.get());
    auto c = std::make_unique<Connection>();
    c->peer = peer_name(fd.get());
    c->fd = std::move(fd);
    c->connected = c->last_activity = Clock::now();
    conns_.push_back(std::move(c));
  }
}

std::size_t ServerLoop::count_strangers(Connection** oldest) const {
  std::size_t strangers = 0;
  *oldest = nullptr;
  for (const auto& c : conns_) {
    if (c->dead || c->pipeserver >= 0) continue;
    ++strangers;
    if (!*oldest || c->connected < (*oldest)->connected) *oldest = c.get();
  }
  return strangers;
}

void ServerLoop::make_room_for_a_stranger() {
  Connection* oldest = nullptr;
  if (count_strangers(&oldest) < kMaxStrangers) return;
  // A burst of connections can arrive between a pipeserver's connect and our first look at
  // it: its HELLO may already be here, unread. Read before judging who said nothing.
  for (std::size_t i = 0; i < conns_.size() && !failure_; ++i) {
    if (!conns_[i]->dead && conns_[i]->pipeserver < 0) read_some(*conns_[i]);
  }
  if (failure_ || count_strangers(&oldest) < kMaxStrangers) return;
  // Logged the first time and every 1000th, so that a flood cannot grow the log without bound.
  if (strangers_evicted_++ % 1000 == 0) {
    log_error(
        fmt::format("{} closed to make room: {} connections had not said HELLO ({} closed "
                    "so far)",
                    who(*oldest), kMaxStrangers, strangers_evicted_));
  }
  close(*oldest, std::nullopt);
}

std::string ServerLoop::who(const Connection& c) const {
  return c.pipeserver >= 0 ? fmt::format("pipeserver {} ({})", c.pipeserver, c.peer)
                           : fmt::format("connection from {}", c.peer);
}

void ServerLoop::read_some(Connection& c) {
  std::size_t budget = kReadBudget;
  while (!c.dead && budget > 0) {
    const bool in_head = !c.head.complete();
    const std::span<std::uint8_t> dst =
        in_head ? c.head.space()
                : std::span<std::uint8_t>(c.body.data() + c.body_got, c.body.size() - c.body_got);
    const ssize_t n = ::recv(c.fd.get(), dst.data(), std::min(dst.size(), budget), 0);
    if (n == 0 || (n < 0 && errno == ECONNRESET)) {
      peer_closed(c, c.head.has_header()
                         ? std::optional<std::string>(
                               fmt::format("{} closed the connection in the middle of a {} message",
                                           who(c), kind_name(c.head.header().kind)))
                         : std::nullopt);
      return;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return;
      peer_closed(c, fmt::format("{}: receive failed: {}", who(c), std::strerror(errno)));
      return;
    }
    c.last_activity = Clock::now();
    budget -= static_cast<std::size_t>(n);
    if (in_head) {
      if (const Status header = c.head.received(static_cast<std::size_t>(n)); !header.ok()) {
        close(c, fmt::format("{}: {}", who(c), header.reason()));
        return;
      }
    } else {
      c.body_got += static_cast<std::size_t>(n);
    }
    if (!advance(c)) return;
  }
}

bool ServerLoop::advance(Connection& c) {
  for (;;) {
    if (!c.head.has_header()) return true;
    const Header& header = c.head.header();
    // A peer that has not said HELLO may say HELLO or ERROR, nothing else: refused here,
    // before a TILE's pixels (up to 48 MiB) are allocated for a stranger.
    if (c.pipeserver < 0 && header.kind != Kind::Hello && header.kind != Kind::Error) {
      close(c, fmt::format("{}: {} before HELLO", who(c), kind_name(header.kind)));
      return false;
    }
    if (!c.head.complete()) return true;
    if (!c.body_ready) {
      // The fixed part is in: size the variable part from it, checked before allocating.
      std::size_t variable = 0;
      if (header.kind == Kind::Tile || header.kind == Kind::TileExt) {
        c.tile = header.kind == Kind::Tile ? decode_tile(c.head.fixed())
                                           : decode_tile_ext(c.head.fixed());
        if (const Status tile = validate(*c.tile, header.payload_bytes); !tile.ok()) {
          close(c, fmt::format("{}: {}", who(c), tile.reason()));
          return false;
        }
        variable = c.tile->pixel_bytes();
      } else if (header.kind == Kind::TileDelta) {
        c.tile = decode_tile_ext(c.head.fixed());
        if (const Status tile = validate_delta(*c.tile, header.payload_bytes); !tile.ok()) {
          close(c, fmt::format("{}: {}", who(c), tile.reason()));
          return false;
        }
        variable = header.payload_bytes - 32;
      } else if (header.kind == Kind::Error) {
        variable = header.payload_bytes;
      }
      if (header.kind == Kind::Tile || header.kind == Kind::TileExt) {
        c.body = assembler_.take_buffer(variable);  // the assembler keeps it: reused
      } else {
        c.body.resize(variable);
      }
      c.body_got = 0;
      c.body_ready = true;
    }
    if (c.body_got < c.body.size()) return true;
    dispatch(c);
    if (c.dead) return false;
    c.head.clear();
    c.tile.reset();
    c.body_ready = false;
    c.body.clear();  // a moved-from tile buffer is left empty; clear() keeps it valid
  }
}

void ServerLoop::dispatch(Connection& c) {
  const Kind kind = c.head.header().kind;
  const std::span<const std::uint8_t> fixed = c.head.fixed();
  if (kind == Kind::Hello) return on_hello(c);
  if (kind == Kind::Error) {
    const std::string_view text(reinterpret_cast<const char*>(c.body.data()), c.body.size());
    close(c, fmt::format("{} gave up: {}", who(c), printable(text)));
    return;
  }
  Status taken;  // c said HELLO: advance() let nothing else through
  if (kind == Kind::Tile || kind == Kind::TileExt) {
    taken = assembler_.add_tile(c.pipeserver, ReceivedTile{*c.tile, std::move(c.body)});
  } else if (kind == Kind::TileDelta) {
    if (!c.deltas) c.deltas.emplace(assembler_.tile_delta_budget());
    Result<std::vector<std::uint8_t>> pixels = c.deltas->decode(*c.tile, c.body);
    taken = pixels.ok() ? assembler_.add_tile(c.pipeserver,
                                              ReceivedTile{*c.tile, std::move(pixels).value()})
                        : Status(Failure{fmt::format("{}: {}", who(c), pixels.reason())});
  } else if (kind == Kind::FrameDone) {
    taken = assembler_.finish(c.pipeserver, decode_frame_done(fixed));
    if (taken.ok() && c.deltas) c.deltas->end_frame();
  } else {
    taken = Failure{fmt::format("unexpected {} from a pipeserver", kind_name(kind))};
  }
  if (!taken.ok()) close(c, fmt::format("{} ({})", taken.reason(), c.peer));
}

void ServerLoop::on_hello(Connection& c) {
  if (c.pipeserver >= 0) {
    close(c, fmt::format("{}: second HELLO", who(c)));
    return;
  }
  const Hello hello = decode_hello(c.head.fixed());
  Status refusal;
  // The token first: a stranger learns nothing about the run (ids, displays) without it.
  if (!same_token(hello.token, options_.token)) {
    refusal = Failure{
        fmt::format("HELLO as pipeserver {} without this run's token", hello.pipeserver_id)};
  } else if (hello.display_count != static_cast<std::uint32_t>(assembler_.display_count())) {
    refusal = Failure{
        fmt::format("HELLO from pipeserver {} announces {} displays, this server composes {}",
                    hello.pipeserver_id, hello.display_count, assembler_.display_count())};
  } else if (hello.pipeserver_id >= static_cast<std::uint32_t>(assembler_.pipeserver_count())) {
    refusal = Failure{fmt::format("pipeserver id {} is outside 0..{}", hello.pipeserver_id,
                                  assembler_.pipeserver_count() - 1)};
  } else {
    refusal = assembler_.connect(static_cast<int>(hello.pipeserver_id));
  }
  if (!refusal.ok()) {
    // A stray or misconfigured peer is turned away with the reason; the run goes on.
    const std::string line = fmt::format("{}: refused: {}", who(c), refusal.reason());
    log_error(line);
    send_error(c, refusal.reason());
    close(c, std::nullopt);
    return;
  }
  c.pipeserver = static_cast<int>(hello.pipeserver_id);
  ++hellos_;
  const auto welcome = encode(Welcome{hello.pipeserver_id, hello.display_count,
                                      static_cast<std::uint32_t>(assembler_.pipeserver_count())});
  queue(c, welcome);
}

void ServerLoop::queue(Connection& c, std::span<const std::uint8_t> bytes) {
  if (c.out_sent == c.out.size()) {
    c.out.clear();
    c.out_sent = 0;
  }
  c.out.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  flush(c);
}

void ServerLoop::flush(Connection& c) {
  while (c.out_sent < c.out.size()) {
    const ssize_t n =
        ::send(c.fd.get(), c.out.data() + c.out_sent, c.out.size() - c.out_sent, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return;
      // The peer is gone; reading will see it and report with the frame in question.
      c.out.clear();
      c.out_sent = 0;
      return;
    }
    c.out_sent += static_cast<std::size_t>(n);
  }
}

// Best effort, never blocks: the peer gets the reason if its socket has room.
void ServerLoop::send_error(Connection& c, const std::string& text) {
  const std::string body = text.substr(0, kMaxErrorText);
  const auto head = encode_error_header(body.size());
  queue(c, head);
  queue(c, std::span(reinterpret_cast<const std::uint8_t*>(body.data()), body.size()));
}

void ServerLoop::close(Connection& c, const std::optional<std::string>& reason) {
  if (c.dead) return;
  // Record first, tell the peer second: whoever hears the ERROR can already read the record.
  if (c.pipeserver >= 0) {
    const Status left = assembler_.disconnect(c.pipeserver);
    if (reason) {
      fail(*reason);
    } else if (!left.ok()) {
      fail(fmt::format("{} ({})", left.reason(), c.peer));
    }
  } else if (reason) {
    log_error(*reason);  // never said HELLO: not one of ours, the run goes on
  }
  if (reason) {
    send_error(c, *reason);
    // Closing with unread input makes the kernel send RST, which can overtake the ERROR just
    // queued; finish our side and swallow what is already here first (bounded).
    ::shutdown(c.fd.get(), SHUT_WR);
    std::uint8_t scratch[4096];
    for (int i = 0; i < 256 && ::recv(c.fd.get(), scratch, sizeof scratch, MSG_DONTWAIT) > 0; ++i) {
    }
  }
  c.dead = true;
  c.fd.reset();
}

void ServerLoop::log_error(const std::string& line) {
  std::lock_guard lock(shared_->mutex);
  if (shared_->error_count++ < kKeptErrors) shared_->errors.push_back(line);
}

void ServerLoop::fail(const std::string& line) {
  if (failure_) return;
  failure_ = line;
  {
    std::lock_guard lock(shared_->mutex);
    ++shared_->error_count;
    shared_->errors.push_back(line);  // kept beyond kKeptErrors: there is only one
    shared_->failure = line;          // published now, before any peer is told
  }
  shared_->changed.notify_all();
}

void ServerLoop::publish_swaps() {
  for (ComposedFrame& composed : assembler_.take_complete()) {
    const FramePtr frame = assembler_.pictures().share(std::move(composed));
    {
      std::lock_guard lock(shared_->mutex);
      shared_->counts += frame->counts;
      shared_->last_swapped = frame->frame;
      shared_->recent.push_back(frame);
      while (shared_->recent.size() > std::max<std::size_t>(options_.recent_frames, 1)) {
        shared_->recent.pop_front();
      }
    }
    shared_->changed.notify_all();
    const auto ack = encode(Swapped{frame->frame});
    for (auto& c : conns_) {
      if (!c->dead && c->pipeserver >= 0) queue(*c, ack);
    }
    if (on_swap_) on_swap_(frame);
  }
}

void ServerLoop::check_timers(Clock::time_point now) {
  if (hellos_ + lost_before_hello_ < assembler_.pipeserver_count() &&
      options_.accept_timeout.count() > 0 && now - started_ > options_.accept_timeout) {
    fail(fmt::format("only {} of {} pipeservers said HELLO within {:.1f} s (listening on {}:{})",
                     hellos_, assembler_.pipeserver_count(), seconds(options_.accept_timeout),
                     options_.host, port_));
    return;
  }
  for (auto& c : conns_) {
    // A peer that connects and never says HELLO would hold a slot forever: same limit, from
    // when it connected (a peer trickling bytes is active but says nothing).
    if (!c->dead && c->pipeserver < 0 && options_.accept_timeout.count() > 0 &&
        now - c->connected > options_.accept_timeout) {
      close(*c, fmt::format("{}: no complete HELLO within {:.1f} s", who(*c),
                            seconds(options_.accept_timeout)));
    }
  }
  if (options_.stall_timeout.count() <= 0) return;
  for (auto& c : conns_) {
    if (c->dead || c->pipeserver < 0) continue;
    if (stalled_mid_message(*c, now)) return;
    const auto waiting = assembler_.frame_waiting_for(c->pipeserver);
    if (waiting != c->waiting_frame) {
      c->waiting_frame = waiting;
      c->waiting_since = now;
    }
    if (!waiting) continue;
    const auto quiet_since = std::max(c->waiting_since, c->last_activity);
    if (now - quiet_since > options_.stall_timeout) {
      fail(fmt::format("{} sent nothing for {:.1f} s while frame {} waits for it", who(*c),
                       seconds(options_.stall_timeout), *waiting));
      return;
    }
  }
}

bool ServerLoop::stalled_mid_message(const Connection& c, Clock::time_point now) {
  const bool mid_message = c.head.bytes_got() > 0;
  if (!mid_message || now - c.last_activity <= options_.stall_timeout) return false;
  fail(fmt::format("{} sent nothing for {:.1f} s in the middle of {}", who(c),
                   seconds(options_.stall_timeout), message_progress(c)));
  return true;
}

// "a TILE message (frame 0, display 0, 4095x4095: 1000 of 50307075 bytes)": what it was
// sending and how far it got.
std::string ServerLoop::message_progress(const Connection& c) const {
  if (!c.head.has_header()) {
    return fmt::format("a message header ({} of {} bytes)", c.head.bytes_got(), kHeaderBytes);
  }
  const char* kind = kind_name(c.head.header().kind);
  if (!c.body_ready) {
    return fmt::format("a {} message ({} of {} bytes)", kind, c.head.bytes_got(),
                       c.head.bytes_needed());
  }
  if (c.tile) {
    return fmt::format("a {} message (frame {}, display {}, {}x{}: {} of {} bytes)", kind,
                       c.tile->frame, c.tile->display, c.tile->w, c.tile->h, c.body_got,
                       c.body.size());
  }
  return fmt::format("a {} message ({} of {} bytes)", kind, c.body_got, c.body.size());
}

void ServerLoop::shut_down() {
  for (auto& c : conns_) {
    if (c->dead) continue;
    if (failure_) send_error(*c, *failure_);
    ::shutdown(c->fd.get(), SHUT_WR);  // deliver what is queued, then FIN
    c->fd.reset();
  }
  conns_.clear();
  listener_.reset();
  {
    std::lock_guard lock(shared_->mutex);
    shared_->failure = failure_;
    shared_->ended = true;
  }
  shared_->changed.notify_all();
}

}  // namespace l2::viz
