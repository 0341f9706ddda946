#!/usr/bin/env bash
# WireGL's figure 9 redrawn: the frame rate of a program that only swaps (`--scene swap`),
# against output size, with 12 pipeservers, on one display and on a 2x2 wall of the same total
# size, through the emulated Lightning-2 at 90 Hz and at full speed, and through the
# visualization server. Writes OUT/fig9.csv and OUT/fig9.png (gnuplot), one run folder per point.
#
#   scripts/fig9.sh [--out DIR] [--frames N] [--sizes "WxH ..."] [--displays "1 4"]
#                   [--modes "dvi90 dvi0 vizserver"] [--build DIR] [--png FILE] [--plot-only]
# --plot-only draws the PNG again from an existing OUT/fig9.csv.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/build/fig9
frames=30
sizes="320x240 640x480 1024x768 1280x1024 1600x1200 2048x1536 2560x1920 3200x2400"
displays="1 4"
modes="dvi90 dvi0 vizserver"
build=$root/build/default
png=
plot_only=0
usage() { sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --out) out=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --displays) displays=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --png) png=$2; shift 2 ;;
    --plot-only) plot_only=1; shift ;;
    -h | --help) usage; exit 0 ;;
    *) echo "fig9: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
png=${png:-$out/fig9.png}
l2wall=$build/l2wall/l2wall
pipeserver=$build/pipeserver/pipeserver
vizserver=$build/vizserver/vizserver
tilelayout=$build/tools/tilelayout/tilelayout
for exe in "$l2wall" "$pipeserver" "$vizserver" "$tilelayout"; do
  [[ -x $exe ]] || { echo "fig9: $exe not built (cmake --build --preset default)" >&2; exit 1; }
done
command -v gnuplot >/dev/null || { echo "fig9: gnuplot not installed (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$out"

# A wall of W x H pixels on `n` displays (1, or a 2x2 grid without mullions), cut into 16 x 12
# tiles (the paper's 100x100 tiles at 1600x1200; on 4 displays 8 x 6 tiles each), 16 to each of the 12 pipeservers, round robin.
# A framebuffer holds its 16 tiles 4 to a row, each with its 2-pixel header gap.
write_wall() {
  local file=$1 w=$2 h=$3 n=$4 fbh_fit=${5:-}
  local c=$((n == 1 ? 1 : 2))  # display columns (and rows)
  local dw=$((w / c)) dh=$((h / c))
  local tw=$(((dw * c + 15) / 16)) th=$(((dh * c + 11) / 12))  # 16/c x 12/c tiles per display
  local fbw=$((4 * (tw + 2))) fbh=${fbh_fit:-$((4 * th))}
  {
    echo "name = \"fig9 ${w}x${h} on $n display(s)\""
    if ((n == 1)); then
      printf '[[display]]\nid = 0\nwidth = %d\nheight = %d\nx = 0\ny = 0\n' "$w" "$h"
    else
      printf '[display_grid]\ncolumns = 2\nrows = 2\nwidth = %d\nheight = %d\n' $((w / 2)) $((h / 2))
      printf 'mullion_x = 0\nmullion_y = 0\n'
    fi
    printf '[tiling]\nkind = "grid"\ntile_width = %d\ntile_height = %d\n' "$tw" "$th"
    printf '[pipeservers]\ncount = 12\nframebuffer_width = %d\nframebuffer_height = %d\n' "$fbw" "$fbh"
    printf 'assignment = "round-robin"\n'
    printf '[mesh]\nboard_max_width = %d\nboard_max_height = %d\nrefresh_hz = 90\n' \
      $((fbw > 1280 ? fbw : 1280)) $((fbh > 1024 ? fbh : 1024))
  } >"$file"
}

# Means over frames 2.. of report.csv (frame 0 renders alone and frame 1's READY wait includes
# every host's start-up): render and READY wait averaged over the hosts too.
# Prints: render_ms route_ms swap_ms ready_wait_ms (n/a where the path has none).
report_means() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i ~ /^render_ms_/) r[i] = 1; if ($i ~ /^ready_wait_ms_/) q[i] = 1 }; next }
    $1 >= 2 { ++n; if ($5 != "") { route += $5; swap += $6; e = 1 }
              for (i in r) { render += $i; ++nr } for (i in q) { wait += $i; ++nq } }
    END { if (!n) { print "n/a n/a n/a n/a"; exit }
          printf "%.3f %s %s %.3f\n", render / nr, e ? sprintf("%.3f", route / n) : "n/a",
                 e ? sprintf("%.3f", swap / n) : "n/a", wait / nq }' "$1"
}

csv=$out/fig9.csv
if ((!plot_only)); then
echo "size,width,height,displays,path,refresh_hz,frames,refreshes,seconds,fps,render_ms,route_ms,swap_ms,ready_wait_ms" >"$csv"
total=0
for _ in $sizes; do for _ in $displays; do for _ in $modes; do total=$((total + 1)); done; done; done
done_runs=0
start=$SECONDS
for size in $sizes; do
  w=${size%x*} h=${size#*x}
  for n in $displays; do
    wall=$out/wall-$size-$n.toml
    write_wall "$wall" "$w" "$h" "$n"
    # Where the display edge cuts the tile grid (e.g. 512 rows in tiles of 86), a pipeserver gets
    # a few more, thinner tiles: take the framebuffer height tilelayout says would fit.
    if ! plan=$("$tilelayout" --wall "$wall" 2>&1); then
      fit=$(grep -o -m1 'framebuffer_height = [0-9]*' <<<"$plan" | grep -o '[0-9]*$') ||
        { echo "fig9: $wall: $plan" >&2; exit 1; }
      write_wall "$wall" "$w" "$h" "$n" "$fit"
      plan=$("$tilelayout" --wall "$wall" 2>&1) || { echo "fig9: $wall: $plan" >&2; exit 1; }
    fi
    if grep -q -i warn <<<"$plan"; then grep -i warn <<<"$plan" | sed "s|^|fig9: $wall: |" >&2; fi
    for mode in $modes; do
      case $mode in
        dvi90) path=dvi refresh=90 ;;
        dvi0) path=dvi refresh=0 ;;
        vizserver) path=vizserver refresh=0 ;;
        *) echo "fig9: unknown mode '$mode' (dvi90, dvi0, vizserver)" >&2; exit 2 ;;
      esac
      run=$out/run-$size-$n-$mode
      rm -rf "$run"
      done_runs=$((done_runs + 1))
      printf '\rfig9: [%d/%d] %s on %d display(s), %s ... (%d s)   ' "$done_runs" "$total" \
        "$size" "$n" "$mode" $((SECONDS - start)) >&2
      if ! "$l2wall" run --wall "$wall" --scene swap --frames "$frames" --refresh "$refresh" \
        --path "$path" --out "$run" --no-progress --pipeserver-program "$pipeserver" \
        --vizserver-program "$vizserver" >"$run.log" 2>&1; then
        echo >&2
        echo "fig9: l2wall run failed for $size on $n display(s), $mode: see $run.log" >&2
        tail -5 "$run.log" >&2
        exit 1
      fi
      # "l2wall run: 30 frames on 1 displays from 12 pipeservers in 0.41 s: 73.2 fps (32 refreshes at 90 Hz)"
      line=$(grep -m1 '^l2wall run: ' "$run/summary.txt")
      seconds=$(sed -E 's/.* in ([0-9.]+) s: .*/\1/' <<<"$line")
      fps=$(sed -E 's/.* s: ([0-9.]+) fps .*/\1/' <<<"$line")
      refreshes=n/a
      [[ $line =~ \(([0-9]+)\ refreshes ]] && refreshes=${BASH_REMATCH[1]}
      read -r render route swap wait < <(report_means "$run/report.csv")
      echo "$size,$w,$h,$n,$path,$refresh,$frames,$refreshes,$seconds,$fps,$render,$route,$swap,$wait" >>"$csv"
    done
  done
done
printf '\rfig9: %d runs in %d s%40s\n' "$total" $((SECONDS - start)) "" >&2
fi

# One curve per path and display count, against output megapixels; the paper's curves as
# references: Lightning-2 at 90 Hz at every size, the visualization server at 8 Hz at 1600x1200.
plot=$out/fig9.gnuplot
curves=()
for mode in $modes; do
  for n in $displays; do
    case $mode in
      dvi90) sel='$5 == "dvi" && $6 == 90' name="Lightning-2 emulated, 90 Hz" ;;
      dvi0) sel='$5 == "dvi" && $6 == 0' name="Lightning-2 emulated, full speed" ;;
      vizserver) sel='$5 == "vizserver"' name="visualization server" ;;
    esac
    data=$out/fig9-$mode-$n.dat
    awk -F, -v n="$n" "NR > 1 && \$4 == n && $sel { print \$2 * \$3 / 1e6, \$10 }" "$csv" >"$data"
    plural=
    ((n > 1)) && plural=s
    curves+=("'$data' using 1:2 with linespoints lw 2 title '$name, $n display$plural'")
  done
done
{
  echo "set terminal pngcairo size 1000,700 font ',11'"
  echo "set output '$png'"
  echo "set title 'SwapBuffers-only frame rate against output size, 12 pipeservers (WireGL fig. 9)'"
  echo "set xlabel 'output image size'"
  echo "set ylabel 'frames per second'"
  echo "set logscale xy"
  echo "set key below maxrows 3"
  echo "set grid"
  echo "set yrange [1:*]"
  echo "set xtics ($(awk -F, 'NR > 1 && !seen[$1]++ { printf "%s\"%s\" %g", sep, $1, $2 * $3 / 1e6; sep = ", " }' "$csv")) rotate by 45 right"
  echo "set arrow from graph 0, first 90 to graph 1, first 90 nohead dt 2 lw 2 lc rgb 'black'"
  echo "set label 'paper: Lightning-2, 90 Hz at every size' at graph 0.55, first 105"
  echo "set object circle at first 1.92, first 8 size screen 0.006 fc rgb 'black' fs solid"
  echo "set label 'paper: visualization server, 8 Hz at 1600x1200' at first 1.92, first 6.3 center"
  printf 'plot %s\n' "$(IFS=,; echo "${curves[*]}")"
} >"$plot"
gnuplot "$plot"
echo "fig9: $csv"
echo "fig9: $png"
