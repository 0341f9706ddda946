#!/usr/bin/env bash
# A screen shared into a session under MPI: only the coordinator rank takes the share's JPEG
# frames (POST /api/share/frame), and sends each pipeserver rank the part of the share its tiles
# show over MPI, as a vnc window's desktop. A checker board of red and blue 32-pixel squares
# (oiiotool's) is shared into examples/sessions/share.toml on the default wall; the displays
# saved then show it in the share's window, 1:1, and the background beside it.
# Usage: mpi_share_test.sh L2WALL OUT NP SOURCE_DIR
set -euo pipefail
l2wall=$1 out=$2 np=$3 source_dir=$4
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
rm -rf "$out" && mkdir -p "$out"
# Enough frames for the share to be taken and shown many times over, then the run ends by
# itself: Ctrl-C on mpirun (SIGTERM to every rank, then SIGKILL) can cut the coordinator off
# before its summary is written.
frames=400
run=""
trap '{ [[ -z $run ]] || kill $run; } 2>/dev/null || true; mpirun_base_remove' EXIT
oiiotool --pattern checker:width=32:height=32:color1=1,0,0:color2=0,0,1 640x360 3 \
  -o "$out/checker.jpg"

"${mpirun_local[@]}" -np "$np" "$l2wall" run --mpi --scene session \
  --session "$source_dir/examples/sessions/share.toml" --frames $frames --keep none \
  --out "$out/mpi" --no-progress --http 127.0.0.1:0 >"$out/mpi.txt" 2>"$out/mpi.err" &
run=$!
url=""
for _ in $(seq 600); do
  url=$(grep -o "http://127.0.0.1:[0-9]*/?token=[0-9a-f]*" "$out/mpi.err" | head -1 || true)
  [[ -n $url ]] && break
  kill -0 $run 2>/dev/null || break
  sleep 0.1
done
[[ -n $url ]] || { echo "FAIL: no control page:"; cat "$out/mpi.err"; exit 1; }
base=${url%%/?token=*} token=${url##*token=}
ask() { curl -s -X POST "$@"; echo; }
for _ in $(seq 600); do  # the run takes requests once its frames go
  curl -s "$base/api/state" | grep -q '"frame":[1-9]' && break
  sleep 0.1
done
ask "$base/api/share?width=640&height=360&name=mpi&token=$token" >"$out/share.json"
grep -q '"done":"sharing mpi as window 1 (640x360) at 330,310 640x360"' "$out/share.json" ||
  { echo "FAIL: share:"; cat "$out/share.json"; exit 1; }
ask --data-binary "@$out/checker.jpg" -H 'Content-Type: image/jpeg' \
  "$base/api/share/frame?window=1&token=$token" >"$out/frame.json"
grep -q '"done":"frame 1 of window 1 taken"' "$out/frame.json" ||
  { echo "FAIL: frame:"; cat "$out/frame.json"; exit 1; }
for _ in $(seq 600); do  # taken by the coordinator into an application frame
  curl -s "$base/api/state" | grep -q '"shown":1' && break
  sleep 0.1
done
# "shown" counts the frames the run took, not what the displays show yet: the frame that took
# it reaches the displays a few refreshes later (pipeservers render it, the boards show it one
# frame after). Wait until every display is five frames past the one showing when it was taken.
displayed() { curl -s "$base/api/state" | python3 -c 'import json, sys; print(json.load(sys.stdin)["frame"])'; }
taken_by=$(($(displayed) + 5))
for _ in $(seq 600); do
  (($(displayed) >= taken_by)) && break
  sleep 0.1
done
ask "$base/api/save?token=$token" >"$out/save.json"
frame=$(grep -o 'frame-[0-9]*' "$out/save.json") ||
  { echo "FAIL: save:"; cat "$out/save.json"; exit 1; }
mpirun_wait $run || { echo "FAIL: the MPI run failed:"; cat "$out/mpi.err"; exit 1; }
run=""

# Display 0 (canvas 0,0 640x480) holds the window's top-left (canvas 330,310): its first square
# red, the next to the right blue, one below blue; canvas 600,100 is the background 0x203040.
oiiotool "$out/mpi/$frame/display-0.png" -o "$out/display-0.ppm"
python3 - "$out/display-0.ppm" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
# "P6 W H 255" and one whitespace byte, then the pixels (whose bytes may look like whitespace).
fields, at = [], 0
while len(fields) < 4:
    while data[at:at + 1].isspace():
        at += 1
    start = at
    while not data[at:at + 1].isspace():
        at += 1
    fields.append(data[start:at])
w, h = int(fields[1]), int(fields[2])
pixels = data[at + 1:]
def at(x, y):
    i = (y * w + x) * 3
    return tuple(pixels[i:i + 3])
def near(c, want):
    return all(abs(a - b) <= 40 for a, b in zip(c, want))
checks = [((346, 326), (255, 0, 0)), ((378, 326), (0, 0, 255)), ((346, 358), (0, 0, 255)),
          ((600, 100), (32, 48, 64))]
for (x, y), want in checks:
    if not near(at(x, y), want):
        print(f"FAIL: display 0 pixel {x},{y} is {at(x, y)}, not near {want}")
        sys.exit(1)
PY
grep -q "shares: window 1 shared by mpi (640x360) from frame" "$out/mpi/summary.txt" ||
  { echo "FAIL: summary:"; cat "$out/mpi/summary.txt"; exit 1; }
echo "the share's checker board on display 0 of $frame, sent over MPI to $((np - 2)) pipeserver ranks"
