#!/usr/bin/env bash
# A session's windows moved under MPI: the coordinator rank decides each frame's WINDOWS line
# and sends it, with the desktop of a vnc window, to every pipeserver rank over MPI
# (mpi_wire::kWindows), as balanced layouts travel. A private Xvnc (loopback only) shows a
# still pattern in a vnc window over the swap scene's window; a line on the MPI run's stdin
# moves the desktop window mid-run. Every frame of the MPI run must be the same bytes as the
# one-machine run of the session as it was (frames before the move) or as moved (from the
# move on): every display switches in the same frame. Usage: mpi_session_test.sh L2WALL OUT NP
set -euo pipefail
l2wall=$1 out=$2 np=$3
frames=24
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
source "$(dirname "$0")/xvnc_local.sh"    # xvnc_local: a private desktop
rm -rf "$out" && mkdir -p "$out"
xvnc="" run=""
trap 'kill $xvnc $run 2>/dev/null; wait $xvnc 2>/dev/null || true; mpirun_base_remove' EXIT
xvnc_local "$out"

session() {  # the desktop window's X and Y
  printf '[[window]]\nsource = "swap"\nx = 100\ny = 100\nwidth = 700\nheight = 500\n'
  printf '[[window]]\nid = 1\nsource = "vnc"\ncontent = "127.0.0.1:%s"\nfit = "stretch"\n' "$display"
  printf 'z = 1\nx = %s\ny = %s\nwidth = 400\nheight = 300\n' "$1" "$2"
}
session 200 150 >"$out/session.toml"
session 600 420 >"$out/moved.toml"
for s in session moved; do
  "$l2wall" run --scene session --session "$out/$s.toml" --frames $frames --keep every \
    --out "$out/one-$s" --no-progress >"$out/one-$s.txt" 2>&1 ||
    { echo "FAIL: the one-machine run of $s.toml failed:"; cat "$out/one-$s.txt"; exit 1; }
done

mkfifo "$out/commands"
"${mpirun_local[@]}" -np "$np" "$l2wall" run --mpi --scene session --session "$out/session.toml" \
  --frames $frames --keep every --out "$out/mpi" --no-progress --window-stdin \
  <"$out/commands" >"$out/mpi.txt" 2>"$out/mpi.err" &
run=$!
exec 4>"$out/commands"
# Until frame 4 is out, or the run has ended early (its failure is said below, from its stderr).
for _ in $(seq 600); do
  [[ -d $out/mpi/frame-4 ]] && break
  kill -0 $run 2>/dev/null || break
  sleep 0.1
done
# A run that has ended reads no more: the line is written with SIGPIPE ignored (in a subshell,
# so the runs keep the default), so that fails the write instead of killing this test unheard.
(trap '' PIPE; echo "move 1 600 420 400 300" >&4) 2>/dev/null || true
exec 4>&-
mpirun_wait $run || { echo "FAIL: the MPI run failed:"; cat "$out/mpi.err"; exit 1; }
run=""

moved=$(grep -n " 1 600 420 400 300" "$out/mpi/windows.txt" | head -1 | cut -d: -f1)
[[ -n $moved ]] || { echo "FAIL: the window never moved:"; cat "$out/mpi.err"; exit 1; }
moved=$((moved - 1))  # windows.txt's line k+1 is frame k
((moved > 4 && moved < frames)) || { echo "FAIL: moved in frame $moved"; exit 1; }
grep -q "windows: move 1 600 420 400 300 from frame $moved" "$out/mpi/summary.txt" ||
  { echo "FAIL: summary:"; cat "$out/mpi/summary.txt"; exit 1; }
for ((k = 0; k < frames; k++)); do
  if ((k < moved)); then want=one-session; else want=one-moved; fi
  for d in 0 1 2 3; do
    cmp -s "$out/$want/frame-$k/display-$d.png" "$out/mpi/frame-$k/display-$d.png" ||
      { echo "FAIL: frame $k display $d differs from $want's"; exit 1; }
  done
done
echo "same bytes: $frames frames x 4 displays, the desktop window moved in frame $moved on every display, $np MPI ranks"
