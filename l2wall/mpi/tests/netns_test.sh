#!/usr/bin/env bash
# The wall across hosts with their own network stacks: scripts/cluster.sh makes each host a
# network namespace with its own address and host name, and runs mpirun across them as on real
# machines. Each display must be the one-machine run's bytes:
#   1. the default wall over 3 hosts (render-a: coordinator + pipeservers 0-1, render-b:
#      pipeservers 2-3, display-a: the column), both paths (--compare);
#   2. a two-column wall with its columns on two hosts (display-a, display-b), and a wall of
#      two meshes (65 displays) with each mesh's columns on a host of its own;
#   3. pipeserver 2 killed, then stopped, on render-b: one line naming it with its host, exit
#      non-zero, and nothing left running on any host;
#   4. the coordinator (rank 0, on render-a) killed: the ranks on the other hosts say so, each in
#      one line naming render-a, through mpirun -q, and end by themselves (cluster.sh names any
#      it had to kill), nothing left, no shared memory;
#   5. --balance strips --survive-host-loss under an mpirun that keeps the job (--keep-job):
#      pipeserver 2 killed on render-b, the run goes on over the other host's and says so, every
#      frame rendered, nothing left running.
# Exit 77 (skipped) where this machine cannot make network namespaces.
# Usage: netns_test.sh L2WALL OUT CLUSTER_SH TWO_COLUMN_WALL TWO_MESH_WALL
set -euo pipefail
l2wall=$1 out=$2 cluster=$3 two_columns=$4 two_meshes=$5
frames=8
rm -rf "$out" && mkdir -p "$out"
source "$(dirname "$0")/rank_pid.sh"
source "$(dirname "$0")/cluster_left.sh"  # nothing_left

# same_displays ONE MPI: every display picture of the last frame of ONE is in MPI, byte for byte.
same_displays() {
  local p n=0
  for p in "$1/frame-$((frames - 1))"/display-*.png; do
    cmp "$p" "$2/frame-$((frames - 1))/$(basename "$p")" || { echo "FAIL: $2 differs"; exit 1; }
    n=$((n + 1))
  done
  ((n > 0)) || { echo "FAIL: $1 has no displays"; exit 1; }
  echo "  $n display pictures of frame $((frames - 1)) the same bytes as on one machine"
}

# 1. The default wall on three hosts, both paths.
"$l2wall" run --path both --compare --frames $frames --refresh 0 --out "$out/one" --no-progress >/dev/null
status=0
bash "$cluster" -- "$l2wall" run --mpi --path both --compare --frames $frames --refresh 0 \
  --out "$out/three-hosts" --no-progress >"$out/three-hosts.txt" 2>"$out/three-hosts.err" || status=$?
if ((status == 77)); then cat "$out/three-hosts.err"; exit 77; fi
((status == 0)) || { echo "FAIL: exit $status"; cat "$out/three-hosts.err"; exit 1; }
# Nothing on stderr (no process left on a host, no fault) but a line Open MPI's rsh launcher
# may print when the agent it started has already made itself a process group (a race it only
# warns of).
if grep -v \
  -e '^\[render-a:[0-9]*\] plm:rsh: Warning: setpgid([0-9]*,[0-9]*) failed in parent with errno=Permission denied(13)$' \
  "$out/three-hosts.err"; then
  echo "FAIL: other lines on stderr"
  exit 1
fi
grep -E "^compare: [0-9]+ display pictures identical byte for byte" "$out/three-hosts.txt" ||
  { echo "FAIL: no compare line"; cat "$out/three-hosts.txt"; exit 1; }
echo "default wall on render-a, render-b, display-a:"
same_displays "$out/one" "$out/three-hosts"

# 2. Two columns on two hosts.
"$l2wall" run --wall "$two_columns" --frames $frames --refresh 0 --out "$out/one-2col" --no-progress >/dev/null
bash "$cluster" --hosts render-a:3,display-a:1,display-b:1 -- "$l2wall" run --wall "$two_columns" \
  --mpi --frames $frames --refresh 0 --out "$out/two-columns" --no-progress >"$out/two-columns.txt" \
  2>&1 || { echo "FAIL: two columns"; cat "$out/two-columns.txt"; exit 1; }
grep -q "over 2 board column rank(s)" "$out/two-columns.txt" ||
  { echo "FAIL: not two column ranks"; cat "$out/two-columns.txt"; exit 1; }
echo "two-column wall, its columns on display-a and display-b:"
same_displays "$out/one-2col" "$out/two-columns"

# Two meshes: ranks 0-4 (coordinator, pipeservers) on render-a, mesh 0's five columns on
# display-a, mesh 1's four on display-b; both paths.
"$l2wall" run --wall "$two_meshes" --frames $frames --refresh 0 --out "$out/one-2mesh" --no-progress >/dev/null
bash "$cluster" --hosts render-a:5,display-a:5,display-b:4 -- "$l2wall" run --wall "$two_meshes" \
  --mpi --path both --compare --frames $frames --refresh 0 --out "$out/two-meshes" --no-progress \
  >"$out/two-meshes.txt" 2>&1 || { echo "FAIL: two meshes"; cat "$out/two-meshes.txt"; exit 1; }
grep -q "over 9 board column rank(s)" "$out/two-meshes.txt" ||
  { echo "FAIL: not nine column ranks"; cat "$out/two-meshes.txt"; exit 1; }
grep -q "^compare: 520 display pictures identical byte for byte" "$out/two-meshes.txt" ||
  { echo "FAIL: paths differ"; cat "$out/two-meshes.txt"; exit 1; }
echo "wall of two meshes, mesh 0's columns on display-a, mesh 1's on display-b:"
same_displays "$out/one-2mesh" "$out/two-meshes"

# 3. Pipeserver 2 (rank 3, on render-b) killed, then stopped, mid-run: one line naming it with
# its host, exit non-zero, nothing left on any host (cluster.sh names what it had to kill).

# start_run DIR: the default wall over three hosts in the background, until its displays have
# swapped a few frames. Sets `run`.
start_run() {
  local dir=$1
  bash "$cluster" -- "$l2wall" run --mpi --frames 100000 --stall-timeout 1000 --ready-timeout 3000 \
    --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  run=$!
  for _ in $(seq 1200); do
    [[ $(cat "$dir"/pipeserver-*.log 2>/dev/null | grep -c '^frame ') -ge 10 ]] && break
    sleep 0.05
  done
}


fault() {
  local signal=$1 dir=$out/$1 run pid pids status=0 line
  start_run "$dir"
  pids=$(pgrep -f -- "$dir" || true)
  pid=$(rank_pid "$dir" 3)
  [[ -n $pid ]] || { echo "FAIL: no process of rank 3"; kill "$run"; exit 1; }
  kill -s "$signal" "$pid"
  wait "$run" || status=$?
  ((status != 0)) || { echo "FAIL: exit 0 after rank 3 got SIG$signal"; exit 1; }
  line=$(grep -E "^l2wall: .*pipeserver 2 \(rank 3 on render-b, pid $pid\).*frame [0-9]+" "$dir.err") ||
    { echo "FAIL: no line naming pipeserver 2 on render-b:"; cat "$dir.err"; exit 1; }
  echo "pipeserver 2 SIG$signal on render-b: $line"
  nothing_left "$dir" "$pids"
}
fault KILL
fault STOP

# 4. The coordinator killed on render-a: mpirun -q says nothing of it, the other ranks do, each
# once, from its liveness connection's close; the run ends, non-zero, nothing left on any host.
coordinator_killed() {
  local dir=$out/coordinator run pid pids status=0
  start_run "$dir"
  pid=$(rank_pid "$dir" 0)
  [[ -n $pid ]] || { echo "FAIL: no process of rank 0"; kill "$run"; exit 1; }
  pids=$(pgrep -f -- "$dir" || true)
  kill -s KILL "$pid"
  wait "$run" || status=$?
  ((status != 0)) || { echo "FAIL: exit 0 after the coordinator was killed"; exit 1; }
  local lost="^l2wall: rank ([0-9]+) on (render-b|display-a): lost the coordinator \(rank 0 on render-a\): its connection closed \(killed or crashed\); this rank ends$"
  grep -qE "$lost" "$dir.err" ||
    { echo "FAIL: no rank on another host named the coordinator's loss:"; cat "$dir.err"; exit 1; }
  if grep -E "$lost" "$dir.err" | sort | uniq -d | grep .; then echo "FAIL: said twice"; exit 1; fi
  echo "coordinator (rank 0) killed on render-a: the run ended, exit $status; $(grep -cE "$lost" "$dir.err") ranks said:"
  grep -E "$lost" "$dir.err" | head -1
  nothing_left "$dir" "$pids"
}
coordinator_killed

# 5. Pipeserver 2 (rank 3, on render-b) killed in a run that survives it: the default wall with
# framebuffers that hold four pipeservers' tiles on three.
survived() {
  local dir=$out/survived run pid pids line
  sed -e 's/framebuffer_width = 800/framebuffer_width = 1024/' \
    -e 's/framebuffer_height = 600/framebuffer_height = 768/' "$(dirname "$0")/../../../walls/kd-2x2.toml" \
    >"$out/roomy.toml"
  bash "$cluster" --keep-job -- "$l2wall" run --mpi --wall "$out/roomy.toml" --balance strips \
    --survive-host-loss --frames 60 --refresh 0 --stall-timeout 60000 --ready-timeout 5000 \
    --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  run=$!
  for _ in $(seq 1200); do
    [[ $(grep -c '^frame ' "$dir"/pipeserver-2.log 2>/dev/null) -ge 5 ]] && break
    sleep 0.05
  done
  pids=$(pgrep -f -- "$dir" || true)
  pid=$(rank_pid "$dir" 3)
  [[ -n $pid ]] || { echo "FAIL: no process of rank 3"; kill "$run"; exit 1; }
  kill -s KILL "$pid"
  # mpirun keeping the job exits 0 whatever the ranks did, 1 when l2wall ended it after the
  # loss (it would wait for ever for the lost rank), as cluster.sh's help says: the output says
  # how the run went.
  status=0
  wait "$run" || status=$?
  [[ $status == 1 ]] || { echo "FAIL: cluster.sh exited $status, its help says 1"; cat "$dir.err"; exit 1; }
  # Open MPI's harmless lines (PMIx's BAD-PARAM, the launcher's setpgid) are not the user's to read.
  if grep -E "PMIX ERROR|plm:rsh: Warning|Epoll MOD" "$dir.err"; then
    echo "FAIL: Open MPI's noise in what the user reads"
    exit 1
  fi
  line=$(grep -E "^l2wall: pipeserver 2 \(rank 3 on render-b, pid $pid\) is gone .* the run goes on without it" "$dir.err") ||
    { echo "FAIL: no line naming pipeserver 2 on render-b gone, the run going on:"; cat "$dir.err"; exit 1; }
  grep -q "^l2wall run: 60 frames on 4 displays" "$dir.out" ||
    { echo "FAIL: not every frame rendered"; cat "$dir.out" "$dir.err"; exit 1; }
  grep -E "^balance: lost pipeserver 2 \(rank 3 on render-b, pid $pid\)" "$dir.out" ||
    { echo "FAIL: the summary does not name the loss"; cat "$dir.out"; exit 1; }
  grep -q "^l2wall: --mpi: ending the job (SIGTERM to mpirun, pid [0-9]*)" "$dir.err" ||
    { echo "FAIL: mpirun was not asked to end the job"; cat "$dir.err"; exit 1; }
  echo "pipeserver 2 SIGKILL on render-b, survived: $line"
  nothing_left "$dir" "$pids"
}
survived
echo "nothing left running on any host"
