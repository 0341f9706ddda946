# rank_pid DIR RANK: the pid of MPI rank RANK among the processes of the run writing to folder
# DIR (no folder name is a prefix of another). mpirun gives each process its rank in its
# environment; a pipeserver rank keeps it across its exec. Sourced by the MPI test scripts.
# grep reads the environment itself (NUL-separated, -z): piped from another command under
# `set -o pipefail`, its early exit on a match could end the writer by SIGPIPE (an environment
# larger than a pipe holds), and the match would count as a failure.
rank_pid() {
  local p
  for p in $(pgrep -f -- "$1" || true); do
    if grep -qzx "OMPI_COMM_WORLD_RANK=$2" "/proc/$p/environ" 2>/dev/null; then
      echo "$p"
      return
    fi
  done
}
