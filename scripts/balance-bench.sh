#!/usr/bin/env bash
# The load balancer's benchmark (balance/, issues 21 and 34): fixed camera paths rendered on 4
# and 8 pipeservers of the default wall, by default of two scenes: `strips` (a cloud turning at
# the centre, which the wall's own tiling is cut for) and `hotspot` (a small cloud travelling
# round the view: static tiling unbalanced), tiled static, by strips and by k-d re-split, each
# with and without the heaviest-first assignment. `hotspot` runs on the default wall with
# 1280x1024 framebuffers (the boards' limit; written to OUT/kd-2x2-1280x1024.toml): the
# balanced cuts of a load in one corner give the pipeserver of the empty rest most of the
# canvas, which 800x600 framebuffers cannot hold (the planner refuses such layouts). Writes OUT/balance.csv (a row per frame: frame time =
# the slowest pipeserver's render time, imbalance = that over the mean, the frame time the last
# frame's estimate predicted, display tiles, overlap factor, whether a new layout was not taken
# for not paying, the scene), OUT/balance.png (frame time per frame) and
# OUT/balance-summary.txt (per scene and configuration: median speed-up over static per frame,
# median, mean and largest imbalance after the first five frames).
#
#   scripts/balance-bench.sh [--out DIR] [--frames N] [--pipeservers "4 8"]
#                            [--scene "strips hotspot"]
#                            [--wall FILE] [--build DIR] [--plot-only] [-- BENCH OPTIONS...]
# --wall: every scene on FILE instead. --plot-only draws the PNG and the summary again from an
# existing OUT/balance.csv. BENCH OPTIONS go to every balance_bench run: scene options, or
# --resistance R --tile-cost F, or --gain G.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/build/balance-bench
frames=40
pipeservers="4 8"
scenes="strips hotspot"
build=$root/build/default
scene_args=()
plot_only=0
wall=
usage() { sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --out) out=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --pipeservers) pipeservers=$2; shift 2 ;;
    --scene) scenes=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --wall) wall=$2; shift 2 ;;
    --plot-only) plot_only=1; shift ;;
    --) shift; scene_args=("$@"); break ;;
    -h | --help) usage; exit 0 ;;
    *) echo "balance-bench: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
bench=$build/tools/balance_bench/balance_bench
((plot_only)) || [[ -x $bench ]] || { echo "balance-bench: $bench not built (cmake --build --preset default --target balance_bench)" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "balance-bench: gnuplot not installed (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$out"
csv=$out/balance.csv
roomy=$out/kd-2x2-1280x1024.toml
sed -e 's/^framebuffer_width = .*/framebuffer_width = 1280/' \
  -e 's/^framebuffer_height = .*/framebuffer_height = 1024/' "$root/walls/kd-2x2.toml" >"$roomy"
wall_of() {
  if [[ -n $wall ]]; then echo "$wall"
  elif [[ $1 == hotspot ]]; then echo "$roomy"
  else echo "$root/walls/kd-2x2.toml"; fi
}
# One rendering thread: every pipeserver is timed alone, so the times compare across runs
# whatever else the machine runs.
export LP_NUM_THREADS=1
if ((!plot_only)); then
echo "pipeservers,mode,assign,frame,frame_ms,imbalance,retiled,predicted_ms,tiles,overlap,resisted,scene" >"$csv"
for scene in $scenes; do
  for p in $pipeservers; do
    for mode in static strips kd; do
      for assign in 0 1; do
        flag=()
        ((assign)) && flag=(--assign)
        "$bench" --wall "$(wall_of "$scene")" --pipeservers "$p" --mode "$mode" "${flag[@]}" \
          --frames "$frames" --scene "$scene" "${scene_args[@]}" | sed "s/\$/,$scene/" >>"$csv"
      done
    done
  done
done
fi

# Per scene and configuration, the median over frames of static's frame time over its own
# (same scene, pipeserver count and frame), and its imbalance after the first five frames.
summary=$out/balance-summary.txt
{
  echo "scene pipeservers mode assign median_speedup median_imbalance mean_imbalance max_imbalance"
  # Static's frame times first (the whole file), then each row against the same frame's.
  awk -F, 'NR == FNR { if (FNR > 1 && $2 == "static" && $3 == 0) base[$12 " " $1 " " $4] = $5; next }
           FNR > 1 { key = $12 " " $1 " " $2 " " $3
                     ratio[key] = ratio[key] " " base[$12 " " $1 " " $4] / $5
                     if ($4 >= 5) imb[key] = imb[key] " " $6 }
           END { for (k in ratio) print k "|" ratio[k] "|" imb[k] }' "$csv" "$csv" |
    while IFS='|' read -r key ratios imbalances; do
      median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
      stats() { tr ' ' '\n' | grep . | awk '{ s += $1; if ($1 > m) m = $1 } END { printf "%.3f %.3f", NR ? s / NR : 0, m }'; }
      printf '%s %.3f %.3f %s\n' "$key" "$(median <<<"$ratios")" "$(median <<<"$imbalances")" \
        "$(stats <<<"$imbalances")"
    done | sort -k1,1 -k2,2n -k3,3 -k4,4n
} >"$summary"

plot=$out/balance.gnuplot
{
  rows=$(($(wc -w <<<"$scenes") * $(wc -w <<<"$pipeservers")))
  echo "set terminal pngcairo size 1000,$((400 * rows + 100)) font ',11'"
  echo "set output '$out/balance.png'"
  echo "set datafile separator ','"
  echo "set multiplot layout $rows,1 title 'frame time per frame (slowest pipeserver)'"
  for scene in $scenes; do
  for p in $pipeservers; do
    echo "set title 'scene $scene, $p pipeservers, $(basename "$(wall_of "$scene")" .toml)'"
    echo "set xlabel 'frame'"
    echo "set ylabel 'frame time (ms)'"
    echo "set key outside right"
    echo "set grid"
    curves=()
    for mode in static strips kd; do
      for assign in 0 1; do
        name=$mode
        ((assign)) && name="$mode + assignment"
        curves+=("'$csv' using (strcol(12) eq '$scene' && \$1 == $p && strcol(2) eq '$mode' && \$3 == $assign ? \$4 : 1/0):5 with lines lw 2 title '$name'")
      done
    done
    printf 'plot %s\n' "$(IFS=,; echo "${curves[*]}")"
  done
  done
  echo "unset multiplot"
} >"$plot"
gnuplot "$plot"
cat "$summary"
echo "balance-bench: $csv"
echo "balance-bench: $out/balance.png"
