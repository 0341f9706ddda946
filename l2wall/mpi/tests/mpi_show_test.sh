#!/usr/bin/env bash
# --show monitors under real mpirun on a private Xvfb: the board column rank opens its display
# fullscreen on the monitor the wall file names, and what that X server shows (read back from
# the window, --show-readback) is byte for byte the picture the run writes of the same frame.
# Usage: mpi_show_test.sh L2WALL OUT WALL (a wall of one column whose displays name Xvfb's
# monitor). Also: --show window is refused with --mpi in one line.
set -euo pipefail
l2wall=$1 out=$2 wall=$3
frames=3
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
mpirun=("${mpirun_local[@]}" -q)
rm -rf "$out" && mkdir -p "$out"
command -v Xvfb >/dev/null || { echo "Xvfb is not installed: skipped"; exit 77; }  # ctest: skipped

# A private X server on a display number it picks itself (-displayfd), so tests never collide.
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$out/display" 2>"$out/xvfb.txt" &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; wait $xvfb 2>/dev/null || true; mpirun_base_remove' EXIT
for _ in $(seq 100); do [[ -s $out/display ]] && break; sleep 0.05; done
[[ -s $out/display ]] || { echo "FAIL: Xvfb did not start"; cat "$out/xvfb.txt"; exit 1; }
export DISPLAY=:$(head -1 "$out/display")

"${mpirun[@]}" -np 4 "$l2wall" run --wall "$wall" --mpi --show monitors --frames $frames \
  --refresh 0 --keep every --out "$out/run" --show-readback "$out/screen" --no-progress \
  >"$out/run.txt" 2>&1 &
mpirun_wait $! || { echo "FAIL: the run failed"; cat "$out/run.txt"; exit 1; }
grep -q "^l2wall run: $frames frames" "$out/run.txt" || { echo "FAIL: no summary"; cat "$out/run.txt"; exit 1; }
for ((k = 0; k < frames; ++k)); do
  shown=$out/screen/frame-$k/display-0.png
  [[ -f $shown ]] || { echo "FAIL: the column showed no frame $k"; ls -R "$out/screen"; exit 1; }
  cmp "$shown" "$out/run/frame-$k/display-0.png" ||
    { echo "FAIL: the screen's frame $k differs from the run's"; exit 1; }
done
echo "the column's monitor showed frames 0-$((frames - 1)) byte for byte"

"${mpirun[@]}" -np 4 "$l2wall" run --wall "$wall" --mpi --show window --frames 1 \
  --out "$out/window" >/dev/null 2>"$out/window.txt" &
if mpirun_wait $!; then
  echo "FAIL: --show window was accepted with --mpi"
  exit 1
fi
grep -qx "l2wall: --mpi: --show window is one machine's; --show monitors shows each column's displays on its own machine's monitors" \
  "$out/window.txt" || { echo "FAIL: no one-line --show window error:"; cat "$out/window.txt"; exit 1; }
echo "--show window refused"

# A column whose displays outnumber its machine's monitors fails before MPI starts: one line
# naming its rank and the monitors it sees, and nothing of the run left running.
"${mpirun[@]}" -np 6 "$l2wall" run --mpi --show monitors --frames 3 --out "$out/few" \
  --no-progress >/dev/null 2>"$out/few.txt" &
if mpirun_wait $!; then
  echo "FAIL: 4 displays on 1 monitor were accepted"
  exit 1
fi
[[ $(<"$out/few.txt") == 'l2wall: board column 0 (rank 5): walls/kd-2x2.toml (built in): --show monitors needs one monitor per display: 4 displays, but GLFW sees 1 monitor: [0] "screen" 800x600 at (0,0)' ]] ||
  { echo "FAIL: not the one line:"; cat "$out/few.txt"; exit 1; }
if pgrep -f -- "--out $out/few" >/dev/null; then
  echo "FAIL: left running:"; pgrep -af -- "--out $out/few"; exit 1
fi
echo "too few monitors refused in one line"
