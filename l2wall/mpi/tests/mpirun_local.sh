# Sourced by the MPI tests: how they start mpirun on this one machine.
#
# Open MPI picks its TCP interfaces when a job starts (the byte transport, btl, and the
# runtime's own out-of-band channel, oob). Left free, it takes every interface up at that
# moment, and one that another process adds or removes mid-run (a network namespace's bridge,
# made and removed by another test) hung a run until its timeout: the ranks tried to reach
# each other over it. Pinned to loopback, what else the machine has never changes a result.
# TCP is forced (btl self,tcp) so the frames really cross sockets, as between hosts.
mpirun_loopback=(mpirun --mca btl self,tcp --mca btl_tcp_if_include lo --mca oob_tcp_if_include lo)
# More ranks than cores: a waiting rank yields its core instead of busy-polling, as the README's
# one-machine commands ask (Open MPI does so by itself under --oversubscribe; said, not assumed).
mpirun_local=("${mpirun_loopback[@]}" --oversubscribe --mca mpi_yield_when_idle 1)
# Root may run mpirun here (containers, CI): said for these tests only, never for the user.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# hwloc's GL plugin (Open MPI's topology) opens X display :0 in every rank; an X server there
# that goes away (another test's Xvfb) ends the rank with an X I/O error.
export HWLOC_COMPONENTS=-gl

# mpirun_wait PID: waits for mpirun PID (started in the background by this shell, `... &`, so
# its pid is known) and returns its exit status. An mpirun that ends without its own cleanup
# (Open MPI 4.1's mpirun now and then crashes in its PMIx server's finalize after the job has
# ended; or it was killed) leaves its session folder, <tmp>/ompi.<host>.<uid>/pid.<its pid>
# (PMIx's store files), which no one else removes: that folder, by its pid and no other, is
# removed here and said in one line, and the host's folder if that left it empty, as mpirun's
# own cleanup does. Sets mpirun_left: 1 if there was one (for a test that asserts a clean end).
mpirun_wait() {
  local pid=$1 status=0 top
  wait "$pid" || status=$?
  # Open MPI's names: the host name up to its first dot, the user's id, TMPDIR or /tmp.
  top=${TMPDIR:-/tmp}/ompi.$(hostname -s).$(id -u)
  mpirun_left=0
  if [[ -e $top/pid.$pid ]]; then
    mpirun_left=1
    rm -rf "${top:?}/pid.$pid"
    rmdir "$top" 2>/dev/null || true
    echo "  (mpirun $pid, exit $status, left its session folder $top/pid.$pid: removed)"
  fi
  return "$status"
}
