#!/usr/bin/env bash
# A rank of an MPI run killed (SIGKILL) or stopped (SIGSTOP) mid-run, on the default wall
# (6 ranks: coordinator, pipeservers 0-3 as ranks 1-4, board column 0 as rank 5): the run must
# end within the stall timeout (plus saving the displays and mpirun's teardown) with one line
# naming the rank, its role, its host and the frame, exit non-zero, and leave no process of the
# run behind. The hosts wait longer for READY than that, so none gives up first.
# Usage: mpi_fault_test.sh L2WALL OUT
set -euo pipefail
l2wall=$1 out=$2
stall_ms=2000
slack_ms=4000  # saving the displays, MPI_Abort and mpirun's teardown of every rank
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$out" && mkdir -p "$out"

# The pid of MPI rank $2 among the processes of run folder $1 (no folder name is a prefix of
# another) (mpirun gives each its rank in
# its environment; a pipeserver rank keeps it across its exec).
rank_pid() {
  local p
  for p in $(pgrep -f -- "$1" || true); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$p"
      return
    fi
  done
}

# fault SIGNAL RANK ROLE
fault() {
  local signal=$1 rank=$2 role=$3 dir="$out/$1-$2"
  mpirun --oversubscribe --mca btl self,tcp -np 6 "$l2wall" run --mpi --frames 100000 \
    --stall-timeout $stall_ms --ready-timeout 3000 --out "$dir" --no-progress >"$dir.out" \
    2>"$dir.err" &
  local run=$!
  # Until the displays have swapped a few frames (the reports grow a line per frame).
  for _ in $(seq 600); do
    [[ $(cat "$dir"/host-*.log 2>/dev/null | wc -l) -ge 20 ]] && break
    sleep 0.05
  done
  local pid
  pid=$(rank_pid "$dir" "$rank")
  [[ -n $pid ]] || { echo "FAIL: no process of rank $rank"; kill "$run"; exit 1; }
  local t0 status=0
  t0=$(date +%s%N)
  kill -s "$signal" "$pid"
  wait "$run" || status=$?
  local took=$((($(date +%s%N) - t0) / 1000000))
  echo "$signal rank $rank ($role): ended after $took ms, exit $status"
  [[ $status -ne 0 ]] || { echo "FAIL: exit 0"; exit 1; }
  ((took <= stall_ms + slack_ms)) || { echo "FAIL: took $took ms"; exit 1; }
  local line
  line=$(grep -E "^l2wall: .*$role \(rank $rank on [^,]+, pid $pid\).*frame [0-9]+" "$dir.err") ||
    { echo "FAIL: no line naming rank $rank:"; cat "$dir.err"; exit 1; }
  echo "  $line"
  [[ $(grep -c "^l2wall: " "$dir.err") -le 2 ]] || { echo "FAIL: more than one fault line"; exit 1; }
  sleep 0.2
  if pgrep -af -- "$dir"; then echo "FAIL: processes of the run left running"; exit 1; fi
}

fault KILL 2 "pipeserver 1"
fault STOP 3 "pipeserver 2"
fault KILL 5 "board column 0"
fault STOP 5 "board column 0"
