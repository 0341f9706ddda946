// mpirun as the MPI tests start it from C++ (as mpirun_local.sh does for the shell tests): its
// session folders in a base of the test's own, and the wait for it.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "wall_run.hpp"

namespace l2::testing_support {

// A folder for mpirun's session folders of this test alone, removed with everything in it when
// the test ends, however it ends: as mpirun_local.sh's mpirun_base (which says why; short, as
// PMIx's socket paths under it must be).
class MpirunBase {
 public:
  MpirunBase() {
    std::string name = "/tmp/l2mpi.XXXXXX";
    if (mkdtemp(name.data()) == nullptr) ADD_FAILURE() << "cannot make " << name;
    path_ = name;
  }
  MpirunBase(const MpirunBase&) = delete;
  MpirunBase& operator=(const MpirunBase&) = delete;
  ~MpirunBase() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// mpirun as the shell tests start it (mpirun_local.sh says why each part): its session folders
// under BASE, root allowed for this test only, no hwloc GL plugin, TCP only and on loopback
// only, so an interface another process adds mid-run is never used, a waiting rank yielding
// its core. NP 6: the default wall's 4 pipeservers, 1 board column, the coordinator.
// `keeps_job`: mpirun keeps the job when a rank dies (--survive-host-loss under --mpi).
inline std::string mpirun(const MpirunBase& base, int np = 6, bool keeps_job = false) {
  return fmt::format(
      "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 HWLOC_COMPONENTS=-gl "
      "mpirun --mca orte_tmpdir_base '{}' --mca btl self,tcp --mca btl_tcp_if_include lo "
      "--mca oob_tcp_if_include lo --oversubscribe --mca mpi_yield_when_idle 1 {}-np {}",
      base.path().string(),
      keeps_job ? "--mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0 " : "", np);
}

// Waits for a run under mpirun, and says in one line a session folder that mpirun left in BASE:
// one that ended without its own cleanup (Open MPI 4.1's now and then crashes in its PMIx
// finalize once the job has ended; or it was killed), as the shell tests' mpirun_wait does.
// BASE, one mpirun's, takes it away with itself.
inline ExitStatus wait_mpirun(WallRun& run, const MpirunBase& base,
                              std::chrono::milliseconds timeout) {
  const ExitStatus status = run.wait(timeout);
  std::error_code ec;
  for (const auto& left : fs::directory_iterator(base.path(), ec))
    std::cout << fmt::format("(mpirun {} left its session folder {}: removed with its base)\n",
                             run.pid(), left.path().string());
  return status;
}

}  // namespace l2::testing_support
