#!/usr/bin/env bash
# Verify time and memory against the number of meshes (issue 51): walls of M meshes of 64
# displays each (M = 1 2 4 7 by default; 8 rows of 8*M columns of WxH panels, two pipeservers a
# panel), each planned, scanned out, routed and checked by `tilelayout --wall --verify`, which
# checks one mesh at a time: time should grow with the meshes, memory stay that of one mesh.
# Prints a table (median of RUNS runs: seconds, seconds a mesh, peak resident memory) and
# writes OUT/mesh-scale.csv with every run.
#
#   scripts/mesh-scale-bench.sh [--meshes "1 2 4 7"] [--runs 3] [--size 640x360]
#                               [--out DIR] [--build DIR]
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
meshes="1 2 4 7"
runs=3
size=640x360
out=$root/build/mesh-scale-bench
build=$root/build/default
usage() { sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --meshes) meshes=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "mesh-scale-bench.sh: unknown option $1 (--help lists them)" >&2; exit 2 ;;
  esac
done
width=${size%x*}
height=${size#*x}
half=$((width / 2))
tilelayout=$build/tools/tilelayout/tilelayout
[[ -x $tilelayout ]] || { echo "mesh-scale-bench.sh: no $tilelayout (build first)" >&2; exit 1; }
mkdir -p "$out"
csv=$out/mesh-scale.csv
echo "meshes,displays,run,seconds,peak_kb" > "$csv"

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

printf '%-7s %-9s %-12s %-14s %s\n' meshes displays "seconds" "s a mesh" "peak MB"
for m in $meshes; do
  wall=$out/meshes-$m.toml
  cat > "$wall" <<TOML
name = "$m meshes of 64 displays"
[display_grid]
columns = $((8 * m))
rows = 8
width = $width
height = $height
[tiling]
kind = "grid"
tile_width = $half
tile_height = $height
[pipeservers]
count = $((128 * m))
framebuffer_width = $((half + 5))
framebuffer_height = $height
TOML
  for ((r = 1; r <= runs; r++)); do
    rm -rf "$out/verify"
    /usr/bin/time -f '%e %M' -o "$out/time" "$tilelayout" --wall "$wall" --verify "$out/verify" \
      > "$out/verify.log" || { echo "mesh-scale-bench.sh: verify failed on $wall (see $out/verify.log)" >&2; exit 1; }
    read -r seconds peak < "$out/time"
    echo "$m,$((64 * m)),$r,$seconds,$peak" >> "$csv"
  done
  s=$(awk -F, -v m="$m" '$1 == m {print $4}' "$csv" | median)
  kb=$(awk -F, -v m="$m" '$1 == m {print $5}' "$csv" | median)
  printf '%-7s %-9s %-12s %-14s %s\n' "$m" $((64 * m)) "$s" "$(awk -v s="$s" -v m="$m" 'BEGIN {printf "%.2f", s / m}')" $((${kb%.*} / 1024))
done
rm -rf "$out/verify"
echo "wrote $csv"
