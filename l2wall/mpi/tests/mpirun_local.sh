# Sourced by the MPI tests: how they start mpirun on this one machine.
#
# Open MPI picks its TCP interfaces when a job starts (the byte transport, btl, and the
# runtime's own out-of-band channel, oob). Left free, it takes every interface up at that
# moment, and one that another process adds or removes mid-run (a network namespace's bridge,
# made and removed by another test) hung a run until its timeout: the ranks tried to reach
# each other over it. Pinned to loopback, what else the machine has never changes a result.
# TCP is forced (btl self,tcp) so the frames really cross sockets, as between hosts.
#
# Every mpirun on a machine keeps its session folder (PMIx's store files, the job's folders) in
# one host folder, <base>/ompi.<host>.<uid>, /tmp by default, and removes that folder when it
# ends: one mpirun starting while another ends then fails ("mkdir ... File exists",
# orte_session_dir failed), as two tests at once (ctest -j2) did. So each test's mpiruns take a
# base of the test's own (orte_tmpdir_base), short as PMIx's socket paths under it must be, and
# the base goes when the test ends, however it ends (the EXIT trap; a test with a trap of its
# own calls mpirun_base_remove in it).
mpirun_base=$(mktemp -d /tmp/l2mpi.XXXXXX)
mpirun_base_remove() { rm -rf "${mpirun_base:?}"; }
trap mpirun_base_remove EXIT
mpirun_loopback=(mpirun --mca orte_tmpdir_base "$mpirun_base" --mca btl self,tcp
  --mca btl_tcp_if_include lo --mca oob_tcp_if_include lo)
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
# ended; or it was killed) leaves its session folder in the test's base: said in one line and
# emptied here, so the test's next mpirun starts from an empty base and is judged on its own.
# Sets mpirun_left: 1 if there was one (for a test that asserts a clean end). A test runs its
# mpiruns one at a time, so whatever is in the base is this one's.
mpirun_wait() {
  local pid=$1 status=0 left
  wait "$pid" || status=$?
  left=$(find "$mpirun_base" -mindepth 1 -maxdepth 2 | sort | tail -n 1)
  mpirun_left=0
  if [[ -n $left ]]; then
    mpirun_left=1
    find "$mpirun_base" -mindepth 1 -delete
    echo "  (mpirun $pid, exit $status, left its session folder $left: removed)"
  fi
  return "$status"
}
