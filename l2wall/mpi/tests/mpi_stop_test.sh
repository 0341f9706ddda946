#!/usr/bin/env bash
# Ctrl-C on mpirun, the way to stop an --mpi run (the control page cannot): mpirun sends SIGTERM
# to every rank at once, and SIGKILL to all as soon as one has ended. The coordinator stops its
# frames at once, writes summary.txt and report.csv of the frames shown and prints its "stopped
# by signal" line, as on one machine; the other ranks wait for its word and end; nothing is left
# running, no shared memory left. Three runs, so that a race between the ranks' ends shows.
# Usage: mpi_stop_test.sh L2WALL OUT
set -euo pipefail
l2wall=$1 out=$2
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
rm -rf "$out" && mkdir -p "$out"
run=
trap '[[ -z $run ]] || kill -s KILL $run 2>/dev/null || true; mpirun_base_remove' EXIT
fail() {
  echo "FAIL: $*"
  cat "$dir.txt" "$dir.err" 2>/dev/null || true
  exit 1
}

for round in 1 2 3; do
  dir=$out/run$round
  "${mpirun_local[@]}" -np 6 "$l2wall" run --mpi --frames 100000 --keep none --out "$dir" \
    --no-progress >"$dir.txt" 2>"$dir.err" &
  run=$!
  # Frame 10 rendered (pipeserver 0's log has a line a frame): the run is well under way.
  for _ in $(seq 600); do
    grep -qs "^frame 10 " "$dir/pipeserver-0.log" && break
    kill -0 $run 2>/dev/null || fail "run $round ended before frame 10"
    sleep 0.1
  done
  grep -qs "^frame 10 " "$dir/pipeserver-0.log" || fail "run $round: no frame 10 within 60 s"
  ranks=$(pgrep -f -- "$dir" | grep -vx "$run" | tr "\n" " ")
  [[ $(wc -w <<<"$ranks") == 6 ]] || fail "run $round: not 6 rank processes: $ranks"
  kill -s INT $run  # Ctrl-C
  for _ in $(seq 300); do  # a ceiling far above the second mpirun gives the ranks
    kill -0 $run 2>/dev/null || break
    sleep 0.1
  done
  kill -0 $run 2>/dev/null && fail "run $round: mpirun still running 30 s after Ctrl-C"
  mpirun_wait $run || true  # mpirun's own status is Open MPI's, not the coordinator's
  run=
  line=$(grep -ho "^l2wall: stopped by signal 15 (Terminated) after [0-9]* frames; report: $dir$" \
    "$dir.txt" "$dir.err") || fail "run $round: no 'stopped by signal' line"
  frames=$(sed 's/.* after \([0-9]*\) frames.*/\1/' <<<"$line")
  ((frames >= 10)) || fail "run $round: stopped after $frames frames, fewer than were rendered"
  grep -q "^l2wall run: $frames frames on 4 displays" "$dir/summary.txt" ||
    fail "run $round: summary.txt: $(head -1 "$dir/summary.txt" 2>/dev/null)"
  # report.csv: a header and a line a frame shown.
  [[ $(wc -l <"$dir/report.csv") == $((frames + 1)) ]] ||
    fail "run $round: report.csv has $(wc -l <"$dir/report.csv") lines for $frames frames"
  if grep -q "MPI_ABORT" "$dir.txt" "$dir.err"; then fail "run $round: a rank aborted"; fi
  for pid in $ranks; do
    # One mpirun killed as it ended is reaped by init, not at once.
    for _ in $(seq 50); do
      [[ $(ps -o stat= -p "$pid" || true) == Z* || -z $(ps -o stat= -p "$pid" || true) ]] && break
      sleep 0.1
    done
    [[ -n $(ps -o stat= -p "$pid" | grep -v '^Z' || true) ]] &&
      fail "run $round: rank process $pid still running: $(ps -o pid,stat,args -p "$pid")"
    compgen -G "/dev/shm/l2-$pid-*" >/dev/null && fail "run $round: shared memory of $pid left"
  done
  echo "ok: run $round stopped after $frames frames"
done
