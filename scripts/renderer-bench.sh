#!/usr/bin/env bash
# Render time per renderer, OSMesa and EGL side by side (`--renderer`): `pipeserver_bench
# --renderers` on the default wall, RUNS times for each scene, every pipeserver rendering the same
# frames with both renderers alternately; prints each run's sum of the pipeservers' medians and
# the median of the runs, with the ratio EGL / OSMesa (OSMesa timed in the same run). Where EGL is
# Mesa's llvmpipe too (a machine without a GPU) the ratio is about 1; on a node with a GPU it
# says what the GPU gains.
#
#   scripts/renderer-bench.sh [--runs N] [--frames N] [--build DIR] [SCENE...]   (default: mesh strips)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
runs=3
frames=30
build=$root/build/default
usage() { sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; }
scenes=()
while (($#)); do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) usage; exit 0 ;;
    -*) echo "renderer-bench.sh: unknown argument $1" >&2; usage >&2; exit 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
((${#scenes[@]})) || scenes=(mesh strips)
bench=$build/pipeserver/pipeserver_bench
[[ -x $bench ]] || { echo "renderer-bench.sh: no $bench: build it first" >&2; exit 1; }

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
for scene in "${scenes[@]}"; do
  results=()
  for ((run = 1; run <= runs; run++)); do
    out=$("$bench" --renderers "$scene" "$frames")
    if ((run == 1)); then grep -E '^  (osmesa|egl): ' <<<"$out" || true; fi
    line=$(grep '^  all pipeservers' <<<"$out") ||
      { echo "renderer-bench.sh: $scene: no EGL figures:"; echo "$out" | tail -1; continue 2; }
    # "  all pipeservers (sum of medians): osmesa O ms, egl E ms: egl / osmesa R"
    read -r o e r < <(sed -n 's/.*osmesa \([0-9.]*\) ms, egl \([0-9.]*\) ms: egl \/ osmesa \([0-9.]*\)/\1 \2 \3/p' <<<"$line")
    echo "$scene run $run: osmesa $o ms, egl $e ms, egl / osmesa $r"
    results+=("$o $e $r")
  done
  o=$(printf '%s\n' "${results[@]}" | awk '{print $1}' | median)
  e=$(printf '%s\n' "${results[@]}" | awk '{print $2}' | median)
  r=$(printf '%s\n' "${results[@]}" | awk '{print $3}' | median)
  echo "$scene, median of $runs runs (a frame of all pipeservers, summed): osmesa $o ms, egl $e ms, egl / osmesa $r"
done
