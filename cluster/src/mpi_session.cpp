#include "cluster/mpi_session.hpp"

#include <mpi.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

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
}

MpiSession::~MpiSession() {
  MPI_Finalize();
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
