#!/usr/bin/env bash
# scripts/fig9.sh in its tiny mode (one size, one display, a few frames, every path): the CSV has
# its columns and one row per path with sane figures, and the PNG is there, a real picture.
# Argument: the build folder.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d /tmp/fig9-test.XXXXXX)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL $*"; exit 1; }
bash "$root/scripts/fig9.sh" --build "$1" --out "$out" --sizes 320x240 --displays 1 --frames 20 \
  >"$out/output.txt" 2>&1 || { cat "$out/output.txt"; fail "fig9.sh exited $?"; }
csv=$out/fig9.csv
want="size,width,height,displays,path,refresh_hz,frames,refreshes,seconds,fps,render_ms,route_ms,swap_ms,ready_wait_ms"
[[ $(head -1 "$csv") == "$want" ]] || fail "CSV header: $(head -1 "$csv")"
[[ $(wc -l <"$csv") -eq 4 ]] || fail "CSV rows: $(cat "$csv")"
# Per row: the run's own size and frame count; fps and render time positive; on the DVI path
# at least one refresh per frame and a route time; on the vizserver path neither.
awk -F, 'NR > 1 {
  ok = $1 == "320x240" && $2 == 320 && $3 == 240 && $4 == 1 && $7 == 20 && $10 > 0 && $11 > 0
  if ($5 == "dvi") ok = ok && $8 >= 20 && $12 > 0 && $13 >= 0 && $14 >= 0
  else ok = ok && $5 == "vizserver" && $8 == "n/a" && $12 == "n/a"
  if (!ok) { print "FAIL row: " $0; bad = 1 }
  paths = paths $5 "/" $6 " "
} END { if (paths != "dvi/90 dvi/0 vizserver/0 ") { print "FAIL paths: " paths; bad = 1 }; exit bad }' "$csv" || exit 1
# At 90 Hz the run is paced by the refresh clock (dvi_link/src/refresh_clock.cpp). Its ticks keep
# to a grid one period apart, and a late tick is late by less than a period, so N frames swapped
# at N ticks span more than N - 2 periods from the run's start: frames / seconds stays below
# N * 90 / (N - 2), 100 fps for 20 frames, however loaded the machine. A run that ignored the
# rate would be much faster, as the full-speed row is.
awk -F, '$5 == "dvi" && $6 == 90 && $10 >= $7 * $6 / ($7 - 2) { exit 1 }' "$csv" ||
  fail "faster than 90 Hz: $(cat "$csv")"
png=$out/fig9.png
[[ $(head -c 8 "$png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "$png is no PNG"
size=$(od -An -tu1 -j16 -N8 "$png" | awk '{ print $3 * 256 + $4 "x" $7 * 256 + $8 }')
[[ $size == 1000x700 ]] || fail "PNG is $size, not 1000x700"
grep -q "fig9: 3 runs in " "$out/output.txt" || fail "no closing progress line: $(cat "$out/output.txt")"
echo "ok   fig9.sh: $(($(wc -l <"$csv") - 1)) rows, PNG $size"
