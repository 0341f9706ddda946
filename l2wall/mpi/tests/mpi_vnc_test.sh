#!/usr/bin/env bash
# A desktop over VNC under MPI: the coordinator rank holds the one RFB connection and sends
# each pipeserver rank the part of each frame's frozen desktop its tiles show, over MPI
# (mpi_wire::kWindows). Against a private Xvnc (loopback only) showing a still pattern, the
# MPI run's last frame must be the same bytes as the one-machine run's, whose displays the
# one-machine test checks against the desktop pixel for pixel; and not black: the desktop
# reached the ranks. Usage: mpi_vnc_test.sh L2WALL OUT NP
set -euo pipefail
l2wall=$1 out=$2 np=$3
frames=5
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
source "$(dirname "$0")/xvnc_local.sh"    # xvnc_local: a private desktop
rm -rf "$out" && mkdir -p "$out"
xvnc=""
trap 'kill $xvnc 2>/dev/null; wait $xvnc 2>/dev/null || true; mpirun_base_remove' EXIT
xvnc_local "$out"

"$l2wall" run --scene vnc --content "127.0.0.1:$display" --frames $frames --out "$out/one" \
  --no-progress >"$out/one.txt" 2>&1 || { echo "FAIL: the one-machine run failed:"; cat "$out/one.txt"; exit 1; }
"${mpirun_local[@]}" -np "$np" "$l2wall" run --mpi --scene vnc --content "127.0.0.1:$display" \
  --frames $frames --out "$out/mpi" --no-progress >"$out/mpi.txt" 2>"$out/mpi.err" &
mpirun_wait $! || { echo "FAIL: the MPI run failed:"; cat "$out/mpi.err"; exit 1; }

shopt -s nullglob
pictures=("$out"/one/frame-$((frames - 1))/display-*.png)
[[ ${#pictures[@]} -eq 4 ]] || { echo "FAIL: the one-machine run wrote ${#pictures[@]} displays"; exit 1; }
for p in "${pictures[@]}"; do
  m="$out/mpi/frame-$((frames - 1))/$(basename "$p")"
  cmp "$p" "$m" || { echo "FAIL: $m differs from $p"; exit 1; }
done
# The pattern's two colours, not black: PNGs of one colour are far smaller.
for p in "${pictures[@]}"; do
  [[ $(stat -c %s "$p") -gt 2000 ]] || { echo "FAIL: $p holds no desktop"; exit 1; }
done
grep -q "^vnc: desktop 1300x980" "$out/mpi.txt" || { echo "FAIL: no vnc line"; cat "$out/mpi.txt"; exit 1; }
echo "same bytes: ${#pictures[@]} displays of frame $((frames - 1)), one machine and $np MPI ranks"
