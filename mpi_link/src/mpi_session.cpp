#include "mpi_link/mpi_session.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <thread>

#include "base/fd.hpp"
#include "base/result.hpp"
#include "base/socket.hpp"
#include "deferred_stop.hpp"
#include "mpi_link/busy_polling.hpp"
#include "mpi_link/coordinator_address.hpp"
#include "mpi_link/liveness.hpp"

namespace l2 {
namespace {

constexpr int kHostBytes = 64;
// This process's session, for abort_all (one session a process).
std::atomic<MpiSession*> live_session = nullptr;
// Far above what MPI_Finalize takes on a loaded machine when every rank is there.
constexpr std::chrono::seconds kFinalizeTimeout{10};

struct WireIdentity {
  int pid = 0;
  int cores = 0;
  int yields = 1;
  std::array<char, kHostBytes> host{};
  std::array<char, 128> stack{};
};

}  // namespace

namespace {

// Calls `expire` (which ends the process) unless disarmed within `timeout`: for the MPI calls
// that wait for every rank, which wait for ever for one that died when mpirun keeps the job.
class Deadline {
 public:
  Deadline(std::chrono::milliseconds timeout, std::function<void()> expire)
      : expire_(std::move(expire)), thread_([this, timeout](std::stop_token) { watch(timeout); }) {}
  ~Deadline() { disarm(); }
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;
  void disarm() {
    {
      const std::lock_guard lock(mutex_);
      disarmed_ = true;
    }
    wake_.notify_all();
  }

 private:
  void watch(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    if (!wake_.wait_for(lock, timeout, [this] { return disarmed_; })) expire_();
  }

  std::function<void()> expire_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool disarmed_ = false;
  std::jthread thread_;  // last: it starts once the rest is built
};

}  // namespace

MpiSession::MpiSession(std::chrono::milliseconds start_timeout,
                       std::chrono::milliseconds liveness_timeout)
    : liveness_timeout_(liveness_timeout) {
  if (const auto launched = launched_rank(); launched && launched->rank != 0) catch_stop_signals();
  Deadline start(start_timeout, [start_timeout] {
    const auto launched = launched_rank();
    if (launched && launched->rank == 0)
      std::fprintf(stderr,
                   "l2wall: --mpi: the run's %d ranks did not all start within %lld ms "
                   "(--start-timeout): a rank died or hung as MPI started it\n",
                   launched->size, static_cast<long long>(start_timeout.count()));
    std::_Exit(1);  // MPI is still starting: nothing of it can be ended cleanly
  });
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw std::runtime_error("MPI_Init failed");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  WireIdentity self;
  self.pid = static_cast<int>(getpid());
  self.cores = static_cast<int>(std::thread::hardware_concurrency());
  self.yields = mpi_yields_when_idle() ? 1 : 0;
  gethostname(self.host.data(), self.host.size() - 1);
  const std::string stack = network_stack_id();
  std::memcpy(self.stack.data(), stack.data(), std::min(stack.size(), self.stack.size() - 1));
  std::vector<WireIdentity> all(static_cast<std::size_t>(size_));
  MPI_Allgather(&self, sizeof self, MPI_BYTE, all.data(), sizeof self, MPI_BYTE, MPI_COMM_WORLD);
  for (const WireIdentity& w : all)
    identities_.push_back(
        {w.pid, std::string(w.host.data()), std::string(w.stack.data()), w.cores, w.yields != 0});
  connect_liveness();
  start.disarm();
  live_session = this;
  if (rank_ == 0)
    pulse_ = std::jthread([this](std::stop_token stop) { pulse(stop); });
  else
    pulse_ = std::jthread([this](std::stop_token stop) { follow_coordinator(stop); });
}

MpiSession::~MpiSession() {
  // The run is being stopped (deferred_stop.hpp): this rank's part is done, and the
  // coordinator's word ends it (follow_coordinator).
  if (rank_is_stopping()) await_coordinator_word();
  say_ended();
  live_session = nullptr;
  // MPI_Finalize waits for every rank, and now and then for ever for one lost under an mpirun
  // that keeps the job (Open MPI 4.1): this rank's part is done, it ends as it would have.
  std::optional<Deadline> end;
  if (const auto launched = launched_rank(); launched && launched->keeps_job)
    end.emplace(kFinalizeTimeout, [] { std::_Exit(0); });
  MPI_Finalize();
}

void MpiSession::say_ended() {
  stop_watching();
  if (pulse_.joinable()) {
    pulse_.request_stop();
    pulse_.join();
  }
  // An end, not a death: the other end no longer takes this connection's close as a fault.
  for (const Fd& fd : liveness_)
    if (fd) send_last_word(fd.get(), kLivenessEnded);
  liveness_.clear();
}

namespace {

constexpr int kMaxOffered = 16;
constexpr auto kReachTimeout = std::chrono::seconds(3);  // per address a rank tries

// What the coordinator broadcasts: where its liveness listener is (coordinator_address.hpp).
struct WireOffer {
  std::uint16_t port = 0;
  std::int32_t count = 0;
  std::array<std::uint32_t, kMaxOffered> addresses{};
};

// Why a rank could not connect, gathered on the coordinator (empty: it did).
using WireReachError = std::array<char, 240>;

WireOffer make_offer(std::uint16_t port) {
  WireOffer offer;
  offer.port = port;
  const std::vector<std::uint32_t> addresses =
      offered_addresses(local_interfaces(), mpi_interface_pin());
  for (const std::uint32_t a : addresses) {
    if (offer.count == kMaxOffered) break;
    offer.addresses[static_cast<std::size_t>(offer.count++)] = a;
  }
  return offer;
}

// Loopback where it joins this rank to the coordinator (`beside` it), else each offered
// address in turn.
Result<Fd> reach(const WireOffer& offer, bool beside) {
  std::vector<std::string> candidates;
  if (beside) {
    candidates.emplace_back("127.0.0.1");
  } else {
    for (int i = 0; i < offer.count; ++i)
      candidates.push_back(ipv4_text(offer.addresses[static_cast<std::size_t>(i)]));
  }
  if (candidates.empty())
    return Failure{fmt::format(
        "the coordinator offered no address: no interface of its, other "
        "than loopback, is up{}",
        mpi_interface_pin().empty() ? ""
                                    : fmt::format(" and in MPI's pin '{}'", mpi_interface_pin()))};
  std::string why;
  for (const std::string& host : candidates) {
    try {
      return connect_tcp(host, offer.port, kReachTimeout, "the coordinator at");
    } catch (const std::exception& e) {
      why += (why.empty() ? "" : "; ") + std::string(e.what());
    }
  }
  return Failure{why};
}

}  // namespace

void MpiSession::connect_liveness() {
  Fd listener;
  WireOffer offer;
  if (rank_ == 0) {
    listener = listen_tcp("0.0.0.0", 0);
    offer = make_offer(local_port(listener.get()));
  }
  MPI_Bcast(&offer, sizeof offer, MPI_BYTE, 0, MPI_COMM_WORLD);
  WireReachError error{};
  std::vector<WireReachError> errors(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
  if (rank_ != 0) {
    Result<Fd> fd = reach(offer, beside(0));
    const std::int32_t me = rank_;
    if (fd.ok() && send(fd->get(), &me, sizeof me, MSG_NOSIGNAL) == sizeof me) {
      liveness_.push_back(std::move(fd).value());
    } else {
      const std::string why = fd.ok() ? "the connection closed at once" : fd.reason();
      std::memcpy(error.data(), why.data(), std::min(why.size(), error.size() - 1));
    }
  }
  // Each rank's word comes once it has connected or given up: the coordinator accepts until
  // every rank has spoken and each that connected is taken in.
  MPI_Request gathered = MPI_REQUEST_NULL;
  MPI_Igather(&error, sizeof error, MPI_BYTE, errors.data(), sizeof error, MPI_BYTE, 0,
              MPI_COMM_WORLD, &gathered);
  if (rank_ == 0) accept_liveness(listener, gathered, errors);
  MPI_Wait(&gathered, MPI_STATUS_IGNORE);
  if (rank_ == 0) refuse_unreached(errors);
  // Every rank waits for the coordinator's word: the run goes on only if all connected.
  int go = 1;
  MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

void MpiSession::accept_liveness(const Fd& listener, MPI_Request& gathered,
                                 const std::vector<std::array<char, 240>>& errors) {
  liveness_.resize(static_cast<std::size_t>(size_));
  int connected = 1;
  std::optional<std::chrono::steady_clock::time_point> deadline;
  for (;;) {
    if (!deadline) {
      int done = 0;
      MPI_Test(&gathered, &done, MPI_STATUS_IGNORE);
      // Every rank has said whether it connected: those that did are in the listener's queue.
      if (done) deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    }
    const int expected =
        deadline ? 1 + static_cast<int>(std::count_if(errors.begin() + 1, errors.end(),
                                                      [](const auto& e) { return e[0] == '\0'; }))
                 : size_;
    if (connected >= expected || (deadline && std::chrono::steady_clock::now() > *deadline)) return;
    pollfd p{listener.get(), POLLIN, 0};
    if (poll(&p, 1, 5) <= 0) continue;
    Fd fd(accept(listener.get(), nullptr, nullptr));
    if (!fd) continue;
    fcntl(fd.get(), F_SETFL, fcntl(fd.get(), F_GETFL) & ~O_NONBLOCK);
    const timeval wait{5, 0};  // a peer that connects and says nothing is not waited for long
    setsockopt(fd.get(), SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    std::int32_t who = -1;
    if (recv(fd.get(), &who, sizeof who, MSG_WAITALL) != sizeof who || who <= 0 || who >= size_ ||
        liveness_[static_cast<std::size_t>(who)])
      continue;             // not one of our ranks: dropped
    set_nodelay(fd.get());  // a word must not wait behind an unacknowledged pulse
    liveness_[static_cast<std::size_t>(who)] = std::move(fd);
    ++connected;
  }
}

void MpiSession::refuse_unreached(const std::vector<std::array<char, 240>>& errors) {
  std::vector<int> unreached;
  for (int r = 1; r < size_; ++r)
    if (errors[static_cast<std::size_t>(r)][0] != '\0') unreached.push_back(r);
  if (unreached.empty()) return;
  const int first = unreached.front();
  const RankIdentity& who = identities_[static_cast<std::size_t>(first)];
  const std::string others = unreached.size() == 1
                                 ? ""
                                 : fmt::format(" ({} ranks in all could not: {})", unreached.size(),
                                               fmt::join(unreached, ", "));
  std::fprintf(stderr,
               "l2wall: --mpi: rank %d on %s cannot reach the coordinator (rank 0 on %s) beside "
               "MPI: %s%s\n",
               first, who.host.c_str(), identities_.front().host.c_str(),
               errors[static_cast<std::size_t>(first)].data(), others.c_str());
  abort_all(1);
}

namespace {

// Asks the process that started this rank to end the job (SIGTERM): mpirun, or its daemon on
// this host (whose end mpirun takes as the job's). Only under an mpirun that keeps the job, and
// only a parent that is one of them. "mpirun, pid 4242", or empty when none was asked.
std::string end_job() {
  const auto launched = launched_rank();
  if (!launched || !launched->keeps_job) return "";
  const pid_t parent = getppid();
  std::FILE* f = std::fopen(fmt::format("/proc/{}/comm", parent).c_str(), "r");
  if (!f) return "";
  char comm[32] = {};
  const bool read = std::fgets(comm, sizeof comm, f) != nullptr;
  std::fclose(f);
  const std::string name = read ? std::string(comm, strcspn(comm, "\n")) : "";
  if (name != "mpirun" && name != "orterun" && name != "orted") return "";
  kill(parent, SIGTERM);
  return fmt::format("{}, pid {}", name, parent);
}

}  // namespace

void MpiSession::end_job_after_loss() {
  if (rank_ != 0 || lost_ranks().empty()) return;
  say_ended();  // the ranks mpirun now ends take it as the coordinator's good end
  if (const std::string parent = end_job(); !parent.empty())
    std::fprintf(stderr,
                 "l2wall: --mpi: ending the job (SIGTERM to %s): Open MPI's mpirun may not end a "
                 "job that lost a rank by itself; every rank's part is done\n",
                 parent.c_str());
}

void MpiSession::end_stopped(int code) {
  stop_watching();  // the ranks now end: no loss of theirs is a fault
  if (pulse_.joinable()) {
    pulse_.request_stop();
    pulse_.join();
  }
  // Out before the word: the ranks end on it, and mpirun then sends this process SIGKILL.
  std::fflush(stdout);
  std::fflush(stderr);
  for (const Fd& fd : liveness_)
    if (fd) send_last_word(fd.get(), kLivenessStopped);
  std::_Exit(code);
}

void MpiSession::abort_all(int code) {
  end_after_word(code, std::chrono::milliseconds(0));
}

void MpiSession::end_as_effect(int code) {
  end_after_word(code, kStopGrace);
}

void MpiSession::end_after_word(int code, std::chrono::milliseconds wait) {
  // A rank that fails while mpirun stops the run (a pipeserver whose READY stopped coming):
  // the coordinator's word ends it (follow_coordinator), once the report is written.
  if (rank_is_stopping()) await_coordinator_word();
  // Another rank's MPI_Abort ends only itself: the coordinator then finds it gone, names it and
  // ends the job. Its own line must reach mpirun first, which ending its daemon could prevent.
  if (const auto launched = launched_rank(); launched && launched->rank == 0) {
    std::fflush(stderr);
    // The other ranks end without a line of their own: the fault is named.
    if (MpiSession* session = live_session)
      for (const Fd& fd : session->liveness_)
        if (fd) send_last_word(fd.get(), kLivenessAborting);
    end_job();
  } else if (MpiSession* session = live_session; session && !session->liveness_.empty()) {
    // Its own line is out (stderr): the coordinator names it by its exit code, as a crash it
    // is not.
    std::fflush(stderr);
    if (const Fd& fd = session->liveness_.front()) send_last_word(fd.get(), failed_word(code));
    std::this_thread::sleep_for(wait);  // follow_coordinator may end this process meanwhile
  }
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; this is for the compiler
}

bool MpiSession::rank_is_stopping() {
  const auto launched = launched_rank();
  return launched && launched->rank != 0 && stop_signal_received() != 0;
}

void MpiSession::await_coordinator_word() {
  std::this_thread::sleep_for(kStopGrace);  // follow_coordinator ends this process meanwhile
  end_by_stop_signal();
}

std::optional<LaunchedRank> launched_rank() {
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!rank || !size) return std::nullopt;
  const auto is = [](const char* name, std::string_view value) {
    const char* v = std::getenv(name);
    return v && value == v;
  };
  return LaunchedRank{std::atoi(rank), std::atoi(size),
                      is("OMPI_MCA_orte_enable_recovery", "1") &&
                          is("OMPI_MCA_orte_abort_on_non_zero_status", "0")};
}

}  // namespace l2
