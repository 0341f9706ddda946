#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the main job on the built-in
# default wall (walls/kd-2x2.toml): the plan with its pictures, then the live wall —
# pipeserver processes, DVI links in shared memory, the emulator and the READY back-channel.
# Everything goes to ${1:-out/default-wall}.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh default >/dev/null
B=build/default
OUT=${1:-out/default-wall}

echo "== the plan of the default wall (pictures in $OUT/layout)"
$B/tools/tilelayout/tilelayout --png "$OUT/layout"
echo "== the live wall"
$B/l2wall/l2wall run --out "$OUT"
echo "== pictures: $OUT/layout/wall.png, $OUT/frame-*/wall.png, $OUT/frame-*/display-*.png"
