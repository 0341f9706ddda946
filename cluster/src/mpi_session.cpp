#include "cluster/mpi_session.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <mpi.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "base/fd.hpp"
#include "vizserver/socket.hpp"

namespace l2 {
namespace {

constexpr int kHostBytes = 64;

struct WireIdentity {
  int pid = 0;
  std::array<char, kHostBytes> host{};
};

}  // namespace

MpiSession::MpiSession() {
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw std::runtime_error("MPI_Init failed");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  WireIdentity self;
  self.pid = static_cast<int>(getpid());
  gethostname(self.host.data(), self.host.size() - 1);
  std::vector<WireIdentity> all(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
  MPI_Gather(&self, sizeof self, MPI_BYTE, all.data(), sizeof self, MPI_BYTE, 0, MPI_COMM_WORLD);
  if (rank_ != 0) all.push_back(self);
  for (const WireIdentity& w : all) identities_.push_back({w.pid, std::string(w.host.data())});
  connect_liveness();
}

MpiSession::~MpiSession() {
  stop_watching();
  // An end, not a death: the coordinator no longer takes this connection's close as a fault.
  if (rank_ != 0 && !liveness_.empty()) send(liveness_.front().get(), "e", 1, MSG_NOSIGNAL);
  liveness_.clear();
  MPI_Finalize();
}

void MpiSession::connect_liveness() {
  std::array<char, 128> address{};
  Fd listener;
  if (rank_ == 0) {
    listener = viz::listen_tcp("0.0.0.0", 0);
    std::array<char, kHostBytes> host{};
    gethostname(host.data(), host.size() - 1);
    const std::string text = fmt::format("{}:{}", host.data(), viz::local_port(listener.get()));
    std::memcpy(address.data(), text.data(), std::min(text.size(), address.size() - 1));
  }
  MPI_Bcast(address.data(), static_cast<int>(address.size()), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank_ != 0) {
    const viz::Endpoint at = viz::parse_endpoint(address.data());
    Fd fd = viz::connect_tcp(at.host, at.port, std::chrono::seconds(30), "the coordinator");
    const std::int32_t me = rank_;
    if (send(fd.get(), &me, sizeof me, MSG_NOSIGNAL) != sizeof me)
      throw std::runtime_error("cannot tell the coordinator who this rank is");
    liveness_.push_back(std::move(fd));
    return;
  }
  liveness_.resize(static_cast<std::size_t>(size_));
  // Every other rank connects now: wait for each (the listener is non-blocking).
  fcntl(listener.get(), F_SETFL, fcntl(listener.get(), F_GETFL) & ~O_NONBLOCK);
  for (int n = 1; n < size_; ++n) {
    Fd fd(accept(listener.get(), nullptr, nullptr));
    std::int32_t who = -1;
    if (!fd || recv(fd.get(), &who, sizeof who, MSG_WAITALL) != sizeof who || who <= 0 ||
        who >= size_)
      throw std::runtime_error("a rank's liveness connection failed");
    liveness_[static_cast<std::size_t>(who)] = std::move(fd);
  }
}

void MpiSession::watch_ranks(std::function<std::string(int)> describe) {
  describe_ = std::move(describe);
  watcher_ = std::jthread([this](std::stop_token stop) { watch(stop); });
}

void MpiSession::stop_watching() {
  if (!watcher_.joinable()) return;
  watcher_.request_stop();
  watcher_.join();
  report_unclaimed();
}

void MpiSession::report_unclaimed() {
  const std::lock_guard lock(line_mutex_);
  if (!lost_line_.empty() && !claimed_.exchange(true))
    std::fprintf(stderr, "l2wall: %s\n", lost_line_.c_str());
}

void MpiSession::watch(std::stop_token stop) {
  while (!stop.stop_requested() && lost_ < 0) {
    std::vector<pollfd> fds;
    std::vector<std::size_t> ranks;  // by entry of fds
    for (std::size_t r = 0; r < liveness_.size(); ++r) {
      if (!liveness_[r]) continue;
      fds.push_back({liveness_[r].get(), POLLIN, 0});
      ranks.push_back(r);
    }
    if (fds.empty()) return;
    if (poll(fds.data(), fds.size(), 5) <= 0) continue;
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const std::size_t r = ranks[i];
      char byte = 0;
      if (recv(fds[i].fd, &byte, 1, MSG_DONTWAIT) > 0) {  // the rank ended well
        liveness_[r].reset();
        continue;
      }
      {
        const std::lock_guard lock(line_mutex_);
        lost_line_ = describe_(static_cast<int>(r));
      }
      lost_ = static_cast<int>(r);
      break;
    }
  }
  if (lost_ < 0) return;
  // The run takes the loss up within milliseconds when it can; if it does not, this process
  // may be ending already (mpirun's SIGTERM): the line must be out first.
  for (int i = 0; i < 30 && !stop.stop_requested() && !claimed_; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  report_unclaimed();
}

std::optional<int> MpiSession::lost_rank() {
  const int r = lost_;
  if (r < 0) return std::nullopt;
  claimed_ = true;
  return r;
}

void MpiSession::abort_all(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; this is for the compiler
}

std::optional<LaunchedRank> launched_rank() {
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!rank || !size) return std::nullopt;
  return LaunchedRank{std::atoi(rank), std::atoi(size)};
}

}  // namespace l2
