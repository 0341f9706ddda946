// Touch over TUIO under MPI (`mpirun -np 6 l2wall run --mpi --tuio`): the coordinator takes
// the tracker's datagrams and steers the session's windows, and each change reaches the
// pipeserver ranks with the frame it belongs to, so every display of the frames around a
// change shows the windows as that frame's WINDOWS line places them, as on one machine
// (touch_run.hpp). Real mpirun over the TCP transport, on loopback.
#include "mpirun_run.hpp"
#include "touch_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

TEST(TouchUnderMpi, ADragAPinchAndATapSwitchInOneFrameOnEveryDisplay) {
  const MpirunBase base;
  expect_touches_switch_in_one_frame("mpi-touch", mpirun(base), {"--mpi"},
                                     [&](WallRun& run) { return wait_mpirun(run, base, 180s); });
}

}  // namespace
}  // namespace l2
