// Lines (MPI_CHAR) sent to one peer without waiting for it to take them (MPI_Isend), their bytes
// kept until each completes. A peer rank that died before taking a line (a pipeserver lost under
// --survive-host-loss, which mpirun keeps the job for) leaves its sends pending for ever: a
// blocking send to it would never return, this one leaves them to the process's end.
#pragma once

#include <mpi.h>

#include <deque>
#include <memory>
#include <string>

namespace l2 {

class MpiOutbox {
 public:
  // MPI must be initialised (MpiSession) and stay so while the outbox lives.
  explicit MpiOutbox(int peer) : peer_(peer) {}
  ~MpiOutbox();
  MpiOutbox(const MpiOutbox&) = delete;
  MpiOutbox& operator=(const MpiOutbox&) = delete;

  // Starts sending `line` under `tag`; false when MPI refuses.
  bool send(std::string line, int tag);
  // Forgets the sends that completed.
  void reap();

 private:
  struct Sending {
    std::unique_ptr<std::string> line;  // stays put until the send completes
    MPI_Request request = MPI_REQUEST_NULL;
  };
  int peer_;
  std::deque<Sending> sending_;
};

}  // namespace l2
