#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the main job on the built-in
# default wall (walls/kd-2x2.toml). Pictures go to ${1:-out/default-wall}.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh default >/dev/null
B=build/default
OUT=${1:-out/default-wall}
mkdir -p "$OUT"

if [ -x $B/l2wall/l2wall ] && $B/l2wall/l2wall run --help >/dev/null 2>&1; then
  # The live wall: pipeserver processes, DVI links in shared memory, the emulator, READY.
  exec $B/l2wall/l2wall run --out "$OUT"
fi

# Until the live run exists, the same chain one stage at a time on frame 0.
WALL=walls/kd-2x2.toml
echo "== plan of the default wall"
$B/tilelayout/tilelayout "$WALL" --png "$OUT/layout" --scanout "$OUT/scanout"
servers=$(ls "$OUT"/scanout/scanout-*.png | wc -l)
echo "== routing the test-pattern frames through the emulator"
$B/lightning2_emu/lightning2_emu route --wall "$WALL" --out "$OUT/test-pattern" \
  $(for ((i = 0; i < servers; i++)); do echo "$OUT/scanout/scanout-$i.png"; done)
echo "== rendering frame 0 of the bunny on every pipeserver"
for ((i = 0; i < servers; i++)); do
  $B/pipeserver/pipeserver --wall "$WALL" --server "$i" --frame 0 --scene mesh \
    --out "$OUT/frames/pipeserver-$i.png"
done
$B/pipeserver/pipeserver --wall "$WALL" --server 0 --frame 0 --scene mesh \
  --out "$OUT/frames/pipeserver-0.png" --reference "$OUT/reference" >/dev/null
echo "== routing the rendered frames through the emulator"
$B/lightning2_emu/lightning2_emu route --wall "$WALL" --out "$OUT/displays" \
  $(for ((i = 0; i < servers; i++)); do echo "$OUT/frames/pipeserver-$i.png"; done)
echo "== pictures: $OUT/layout/wall.png, $OUT/displays/wall.png, $OUT/displays/display-*.png"
