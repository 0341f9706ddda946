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
