# rank_pid DIR RANK: the pid of MPI rank RANK among the processes of the run writing to folder
# DIR (no folder name is a prefix of another). mpirun gives each process its rank in its
# environment; a pipeserver rank keeps it across its exec. Sourced by the MPI test scripts.
rank_pid() {
  local p
  for p in $(pgrep -f -- "$1" || true); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$p"
      return
    fi
  done
}
