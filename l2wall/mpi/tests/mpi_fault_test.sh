#!/usr/bin/env bash
# A rank of an MPI run killed (SIGKILL) or stopped (SIGSTOP) mid-run: on the default wall
# (6 ranks: coordinator, pipeservers 0-3 as ranks 1-4, board column 0 as rank 5) and on a
# two-column wall (5 ranks: pipeservers 0-1, columns 0-1 as ranks 3-4). The run must end on its
# own with one line naming the rank, its role, its host and the frame, exit non-zero, and leave
# no process of the run and no shared memory behind. What the displays showed is saved in OUT/fault/, by the coordinator
# from every column still answering (after a rank stopped; after one killed, when that beats
# mpirun's end of the job): each saved display must be the one-machine run's picture
# of the frame the line says the displays keep; a lost column's displays are named, not saved.
# The hosts wait longer for READY than that, so none gives up first.
# Then a pipeserver rank that fails by its own error: named by its exit code, once.
# Last, the coordinator (rank 0) killed: mpirun names it and ends every other rank.
# Usage: mpi_fault_test.sh L2WALL OUT TWO_COLUMN_WALL
set -euo pipefail
l2wall=$1 out=$2 two_columns=$3
stall_ms=1000
# How long a run may take to end after the fault before it counts as hung: ten times what the
# slowest case takes on an idle machine. Ending is asserted, not its speed: the stall timeout,
# saving the displays, MPI_Abort and mpirun's teardown of every rank all stretch on a loaded
# machine (a sanitizer build beside the suite), and a bound near the idle time failed there
# for nothing. A run that never ends is still caught, and killed, at this ceiling.
end_ceiling_ms=15000
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
source "$(dirname "$0")/rank_pid.sh"
rm -rf "$out" && mkdir -p "$out"

# The displays saved in $1/fault/ against the one-machine run of wall $2 (empty: the default)
# at frame $3; $4: the display ids that must be there, the others must not.
check_saved() {
  local dir=$1 wall=${2:+--wall $2} frame=$3 expected=$4 id
  "$l2wall" run $wall --frames $((frame + 1)) --refresh 0 --out "$dir-one" --no-progress >/dev/null
  for p in "$dir-one/frame-$frame"/display-*.png; do
    id=$(basename "$p" .png) id=${id#display-}
    if [[ " $expected " == *" $id "* ]]; then
      cmp "$p" "$dir/fault/display-$id.png" || { echo "FAIL: saved display $id is not frame $frame"; exit 1; }
    elif [[ -e $dir/fault/display-$id.png ]]; then
      echo "FAIL: display $id saved, but its column is gone"
      exit 1
    fi
  done
  echo "  saved displays $expected: frame $frame's pixels"
}

# signal_and_wait SIGNAL PID RUN DIR LABEL: sends SIGNAL to PID, then waits for mpirun (RUN) to
# end, at most end_ceiling_ms; it must end non-zero. Sets `status`, `mpirun_left` and `hung`.
# Open MPI 4.1's mpirun now and then hangs (in a futex) after every rank of the job has exited,
# leaving them unreaped: that is the runtime's, not the run's (each rank ended, as it must), so
# mpirun is then killed and the test goes on, saying so; a rank still alive is a hang of ours.
signal_and_wait() {
  local signal=$1 pid=$2 run=$3 dir=$4 label=$5 t0 took ranks
  status=0 hung=0
  t0=$(date +%s%N)
  kill -s "$signal" "$pid"
  while kill -0 "$run" 2>/dev/null; do
    took=$((($(date +%s%N) - t0) / 1000000))
    ranks=$(ps -o stat= --ppid "$run" || true)
    if ((took > end_ceiling_ms)) && [[ -n $ranks ]] && ! grep -qv '^Z' <<<"$ranks"; then
      echo "  (mpirun hung $took ms after every rank had exited, Open MPI's teardown: killed)"
      hung=1
      kill -s KILL "$run" 2>/dev/null || true
      break
    fi
    if ((took > end_ceiling_ms)); then
      echo "FAIL: $label: still running $took ms after the fault; what it said, and what runs:"
      cat "$dir.err"
      ps -o pid,stat,wchan:24,etime,args --ppid "$run" -p "$run" $(pgrep -f -- "$dir" | sed 's/^/-p /') || true
      kill -s KILL -- $(pgrep -f -- "$dir") "$run" 2>/dev/null || true
      mpirun_wait "$run" || true  # its session folder, which a killed mpirun leaves
      exit 1
    fi
    sleep 0.05
  done
  mpirun_wait "$run" || status=$?
  took=$((($(date +%s%N) - t0) / 1000000))
  echo "$label: ended after $took ms, exit $status"
  [[ $status -ne 0 ]] || { echo "FAIL: exit 0"; exit 1; }
}

# nothing_left DIR PIDS [CRASHED]: no process of the run in DIR, no shared memory of PIDS, no
# session folder left by mpirun (mpirun_left, from mpirun_wait). mpirun has returned; the ranks
# it ended may still be exiting on a loaded machine: allowed a few seconds, not a fixed moment.
# CRASHED (1: mpirun crashed in its PMIx finalize, see fault()): a crash that early skips
# mpirun's removal of its own session folder, which is then Open MPI's litter, not the run's
# (mpirun_wait removed it and said so); the rest still checked.
nothing_left() {
  local dir=$1 pids=$2 crashed=${3:-0} waited p
  for ((waited = 0; waited < 100; ++waited)); do
    pgrep -f -- "$dir" >/dev/null || break
    sleep 0.1
  done
  if pgrep -af -- "$dir"; then echo "FAIL: processes of the run left running"; exit 1; fi
  for p in $pids; do
    if compgen -G "/dev/shm/l2-$p-*" >/dev/null; then echo "FAIL: /dev/shm/l2-$p-* left"; exit 1; fi
  done
  if ((mpirun_left && !crashed)); then echo "FAIL: mpirun's session left"; exit 1; fi
}

# fault SIGNAL RANK ROLE NP WALL SAVED (the display ids saved; empty: none, no fault/ folder;
# maybe:IDS: those if any). The run's timeouts: `timeouts`; its folder: `dir`, after.
timeouts=(--stall-timeout $stall_ms --ready-timeout 3000)
also_said=()  # grep -e arguments: other lines the case expects on stderr
fault() {
  local signal=$1 rank=$2 role=$3 np=$4 wall=$5 saved=$6
  dir="$out/$1-$2-$4${7:-}"
  "${mpirun_local[@]}" -q -np "$np" "$l2wall" run ${wall:+--wall "$wall"} --mpi \
    --frames 100000 "${timeouts[@]}" --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  local run=$!
  # Until the displays have swapped a few frames (the reports grow a line per frame).
  for _ in $(seq 600); do
    [[ $(cat "$dir"/pipeserver-*.log 2>/dev/null | grep -c '^frame ') -ge 10 ]] && break
    sleep 0.05
  done
  local pid pids
  pid=$(rank_pid "$dir" "$rank")
  pids=$(pgrep -f -- "$dir" || true)
  [[ -n $pid ]] || { echo "FAIL: no process of rank $rank"; kill "$run"; exit 1; }
  signal_and_wait "$signal" "$pid" "$run" "$dir" "$signal rank $rank ($role, -np $np)"
  local line
  line=$(grep -E "^l2wall: .*$role \(rank $rank on [^,]+, pid $pid\).*frame [0-9]+" "$dir.err") ||
    { echo "FAIL: no line naming rank $rank:"; cat "$dir.err"; exit 1; }
  echo "  $line"
  [[ $(grep -c "^l2wall: " "$dir.err") -le 2 ]] ||
    { echo "FAIL: more than one fault line:"; grep "^l2wall: " "$dir.err"; exit 1; }
  # mpirun -q: none of mpirun's own messages beside ours. Open MPI's event library may still warn
  # once about the dead rank's socket ("[warn] Epoll MOD(1) on fd 25 failed ... Bad file
  # descriptor"), one run in a few: that line is the runtime's, which -q does not reach. So are
  # the coordinator's TCP transport's two lines when the killed rank's socket is reset under a
  # send already under way (writev: Connection reset by peer, then the endpoint's state): the
  # kernel resets it when the rank dies, before anyone can know. Any rank's blocking receive from
  # the killed one may report the same reset (btl_tcp_recv_blocking). A rank stopped resets
  # nothing.
  local runtime=(-e "^l2wall: " -e "^\[warn\] Epoll [A-Z]*([0-9]*) on fd [0-9]* failed")
  runtime+=("${also_said[@]}")
  [[ $signal != KILL ]] || runtime+=(
    -e "^\[[^]]*\]\[\[[0-9]*,[0-9]*\],0\]\[[^]]*/btl_tcp_frag\.c:[0-9]*:mca_btl_tcp_frag_send\] mca_btl_tcp_frag_send: writev failed: Connection reset by peer (104)$"
    -e "^\[[^]]*\]\[\[[0-9]*,[0-9]*\],0\]\[[^]]*/btl_tcp_endpoint\.c:[0-9]*:mca_btl_tcp_endpoint_send_handler\] invalid connection state ([0-9]*)$"
    -e "^\[[^]]*\]\[\[[0-9]*,[0-9]*\],[0-9]*\]\[[^]]*/btl_tcp\.c:[0-9]*:mca_btl_tcp_recv_blocking\] recv([0-9]*) failed: Connection reset by peer (104)$")
  # mpirun itself (Open MPI 4.1) now and then crashes in its PMIx server's finalize as it ends
  # the job a rank's MPI_Abort ended, after our lines are out and every rank is gone: its own
  # report, lines "[host:<mpirun's pid>] ...", is taken only with that function in it.
  local crashed=$hung  # a hung mpirun, killed, leaves its session folder too
  if grep -q "^\[[^]:]*:$run\] " "$dir.err"; then
    crashed=1
    grep -q "PMIx_server_finalize" "$dir.err" ||
      { echo "FAIL: mpirun crashed, not in its PMIx finalize:"; cat "$dir.err"; exit 1; }
    echo "  (mpirun itself crashed in Open MPI's PMIx_server_finalize after the run ended)"
    runtime+=(-e "^\[[^]:]*:$run\] ")
  fi
  if grep -v "${runtime[@]}" "$dir.err"; then
    echo "FAIL: other lines on stderr"
    exit 1
  fi
  # A rank killed: mpirun ends every rank within about a second, and the coordinator does not
  # always have the displays saved first; when it does, they must be right.
  if [[ $saved == maybe:* ]]; then
    saved=${saved#maybe:}
    grep -q "displays as they were" "$dir.err" || { echo "  (not saved before mpirun's end)"; saved=""; }
  fi
  if [[ -n $saved ]]; then
    local frame note=""
    frame=$(sed -nE 's/.*the displays keep frame ([0-9]+)$/\1/p' <<<"$line")
    [[ -n $frame ]] || { echo "FAIL: the line names no frame kept"; exit 1; }
    [[ $saved == "0 1 2 3 4 5 6 7" ]] && note=" (not display 8: lost with its rank)"
    grep -qxF "l2wall: displays as they were: $dir/fault/$note" "$dir.err" ||
      { echo "FAIL: no line saying where the displays are:"; cat "$dir.err"; exit 1; }
    check_saved "$dir" "$wall" "$frame" "$saved"
  elif [[ $6 != maybe:* ]] && { [[ -e $dir/fault ]] || grep -q "displays as they were" "$dir.err"; }; then
    echo "FAIL: displays saved, but every display was on the rank that is gone"
    exit 1
  fi
  nothing_left "$dir" "$pids" "$crashed"
}

fault KILL 2 "pipeserver 1" 6 "" "maybe:0 1 2 3"
fault STOP 3 "pipeserver 2" 6 "" "0 1 2 3"
fault KILL 5 "board column 0" 6 "" ""
# A column stopped: column 1 (display 8) on the two-column wall; column 0's displays are saved.
fault STOP 4 "board column 1" 5 "$two_columns" "0 1 2 3 4 5 6 7"

# A pipeserver rank stopped while the others' READY wait is the shorter (the liveness timeout and
# the stall timeout far longer): they give up waiting for READY (exit code 3), an effect; the
# run names the stopped one as the cause, as on one machine, never one that gave up.
timeouts=(--stall-timeout 20000 --liveness-timeout 20000 --ready-timeout 500)
also_said=(-e "^pipeserver [013]: frame [0-9]*: no READY for frame [0-9]* on MPI rank 0 (coordinator)")
fault STOP 3 "pipeserver 2" 6 "" "0 1 2 3" -gave-up
cause="^l2wall: pipeserver 2 \(rank 3 on [^,]+, pid [0-9]+\) stopped answering: it did not deliver"
cause+=" frame [0-9]+, and pipeserver [013] gave up waiting for READY \(exited with code 3\); the"
cause+=" displays keep frame [0-9]+$"
grep -qE "$cause" "$dir.err" || { echo "FAIL: not named as the cause:"; cat "$dir.err"; exit 1; }

# A pipeserver rank that fails by its own error (its report cannot be written on its host: the
# log a dangling link) prints its own line, then says its exit code on its liveness connection:
# the coordinator names it by that code, once, as a child's exit on one machine, never as a rank
# killed or crashed.
own_error() {
  local dir="$out/own-error" pids
  mkdir -p "$dir" && ln -s /nonexistent/l2wall-test/pipeserver.log "$dir/pipeserver-1.log"
  "${mpirun_local[@]}" -q -np 6 "$l2wall" run --mpi --frames 100000 --stall-timeout $stall_ms \
    --ready-timeout 3000 --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  local run=$! status=0
  mpirun_wait $run || status=$?
  pids=$(pgrep -f -- "$dir" || true)
  echo "own error of rank 2 (pipeserver 1, -np 6): exit $status"
  [[ $status -ne 0 ]] || { echo "FAIL: exit 0"; exit 1; }
  grep -qxF "pipeserver 1: cannot write report $dir/pipeserver-1.log" "$dir.err" ||
    { echo "FAIL: no line of the pipeserver's own:"; cat "$dir.err"; exit 1; }
  local line="^l2wall: pipeserver 1 \(rank 2 on [^,]+, pid [0-9]+\) exited with code 1 while"
  line+=" the displays wait for frame 0; no frame reached the displays$"
  [[ $(grep -cE "$line" "$dir.err") -eq 1 ]] ||
    { echo "FAIL: not named once by its exit code:"; cat "$dir.err"; exit 1; }
  grep -E "$line" "$dir.err" | sed 's/^/  /'
  ! grep -q "killed or crashed" "$dir.err" || { echo "FAIL: named as killed"; exit 1; }
  nothing_left "$dir" "$pids"
}
own_error

# The coordinator (rank 0) killed: it is named by mpirun (without -q), or, when the other ranks
# see its connection close before mpirun sees it die (then mpirun reports their exit instead), by
# those ranks in their lines naming rank 0 (liveness.hpp); every rank ends, and nothing of the run
# is left, on this host or in /dev/shm.
coordinator_killed() {
  local dir="$out/KILL-0-6"
  "${mpirun_local[@]}" -np 6 "$l2wall" run --mpi --frames 100000 --stall-timeout $stall_ms \
    --ready-timeout 3000 --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  local run=$!
  for _ in $(seq 600); do
    [[ $(cat "$dir"/pipeserver-*.log 2>/dev/null | grep -c '^frame ') -ge 10 ]] && break
    sleep 0.05
  done
  local pid pids
  pid=$(rank_pid "$dir" 0)
  pids=$(pgrep -f -- "$dir" || true)
  [[ -n $pid ]] || { echo "FAIL: no process of rank 0"; kill "$run"; exit 1; }
  signal_and_wait KILL "$pid" "$run" "$dir" "KILL rank 0 (coordinator, -np 6)"
  local lost="^l2wall: rank [1-5] on [^:]*: lost the coordinator (rank 0 on [^)]*): its connection"
  lost+=" closed (killed or crashed); this rank ends$"
  grep -q "mpirun noticed that process rank 0 with PID [0-9]* on node [^ ]* exited on signal 9" "$dir.err" ||
    grep -q "$lost" "$dir.err" ||
    { echo "FAIL: rank 0 named neither by mpirun nor by another rank:"; cat "$dir.err"; exit 1; }
  nothing_left "$dir" "$pids"
}
coordinator_killed
