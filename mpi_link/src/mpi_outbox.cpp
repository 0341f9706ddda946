#include "mpi_link/mpi_outbox.hpp"

namespace l2 {

MpiOutbox::~MpiOutbox() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) reap();
  // A send the peer never took (it ended first, or is gone): it may still complete later, so
  // its line is left to the process's end. Too late to ask MPI once it is finalized.
  for (Sending& s : sending_) {
    if (!finalized) MPI_Request_free(&s.request);
    static_cast<void>(s.line.release());
  }
}

void MpiOutbox::reap() {
  while (!sending_.empty()) {
    int done = 0;
    MPI_Test(&sending_.front().request, &done, MPI_STATUS_IGNORE);
    if (!done) return;
    sending_.pop_front();
  }
}

bool MpiOutbox::send(std::string line, int tag) {
  reap();
  Sending s{std::make_unique<std::string>(std::move(line)), MPI_REQUEST_NULL};
  if (MPI_Isend(s.line->data(), static_cast<int>(s.line->size()), MPI_CHAR, peer_, tag,
                MPI_COMM_WORLD, &s.request) != MPI_SUCCESS)
    return false;
  sending_.push_back(std::move(s));
  return true;
}

}  // namespace l2
