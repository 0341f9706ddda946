#!/usr/bin/env bash
# What the wall asks of a real network, measured (docs/mpi-design.md, "Frames that fit the
# network"). Two parts, one CSV each, in OUT:
#   bytes.csv  megabytes a frame into the board columns, raw (as scanned out, each input's frame
#              to every column it feeds, as sent before frames travelled as changes) and on the
#              wire with --link-codec zstd, as between machines (averaged over the run, and a
#              frame after the first, which starts from black), on the DVI path and the
#              vizserver path, for the default and 4x3 walls and the mesh, swap, picture (panned
#              and zoomed), still (a movie of one still picture) and movie scenes (mpirun on this
#              machine, loopback);
#   fps.csv    frames/s of the wall on the namespace cluster (scripts/cluster.sh) with its links
#              shaped to 1 and 10 Gbit/s and unshaped, frames sent as changes (zstd, what auto
#              chooses between machines) and whole (as before they travelled as changes), and
#              both paths at once as changes (DVI frames and the vizserver path's tiles),
#              against the one-machine run (no MPI) and MPI on loopback (auto: whole);
# and network.png, frames/s against link rate per wall. Needs root for the namespaces.
#
#   scripts/network-bench.sh [--frames N] [--out DIR] [--build DIR] [--only bytes|fps] [--plot-only]
# (--plot-only draws network.png again from OUT/fps.csv)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=30 out=$root/build/network-bench build=$root/build/default only=
usage() { sed -n '/^#   scripts/p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --frames) frames=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --build) build=${2:?}; shift 2 ;;
    --only) only=${2:?}; shift 2 ;;
    --plot-only) only=plot; shift ;;
    -h | --help) usage; exit 0 ;;
    *) echo "network-bench.sh: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done
l2wall=$build/l2wall/l2wall
[[ -x $l2wall ]] || { echo "network-bench.sh: no $l2wall: build it first" >&2; exit 1; }
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 HWLOC_COMPONENTS=-gl
# MPI on this machine: loopback only, whatever other interfaces it has; a waiting rank yields
# its core (more ranks than cores).
local_mpirun=(mpirun -q --oversubscribe --mca btl self,tcp --mca btl_tcp_if_include lo
  --mca oob_tcp_if_include lo --mca mpi_yield_when_idle 1)
declare -A np=([default]=6 [4x3]=11)
declare -A wall_arg=([default]="" [4x3]="--wall $root/walls/monitors-4x3.toml")
# The hosts of each wall on the cluster: the coordinator and half the pipeservers, the other
# half, and one host per board column.
declare -A hosts=([default]=render-a:3,render-b:2,display-a:1
  [4x3]=render-a:5,render-b:4,display-a:1,display-b:1)

# Content for the picture and movie scenes, made here (ffmpeg's test sources).
picture=$out/mandelbrot.png movie=$out/testsrc.mkv still=$out/still.mkv
[[ -s $picture ]] || ffmpeg -loglevel error -y -f lavfi -i mandelbrot=size=3840x2160 -frames:v 1 "$picture"
[[ -s $still ]] || ffmpeg -loglevel error -y -loop 1 -i "$picture" -t 4 -r 30 -vf scale=1920:1080 \
  -c:v ffv1 "$still"
[[ -s $movie ]] || ffmpeg -loglevel error -y -f lavfi -i testsrc2=size=1280x720:rate=30 -t 4 \
  -c:v ffv1 "$movie"
declare -A scene_args=([mesh]="--scene mesh" [swap]="--scene swap"
  [picture]="--scene picture --content $picture" [still]="--scene movie --content $still"
  [movie]="--scene movie --content $movie")

field() { sed -n "$2" "$1" | head -1; }
fps_of() { field "$1" 's/^l2wall run: .*: \([0-9.]*\) fps.*/\1/p'; }

if [[ -z $only || $only == bytes ]]; then
  echo "wall,scene,dvi_raw_mb,dvi_wire_mb,dvi_ratio,dvi_after_first_mb,tiles_raw_mb,tiles_wire_mb,tiles_ratio,tiles_after_first_mb" \
    >"$out/bytes.csv"
  # "X MB a frame on the wire (Y MB raw, Zx less; the first F MB, then A MB a frame)" -> Y,X,Z,A
  sent='\([0-9.]*\) MB a frame on the wire (\([0-9.]*\) MB raw, \([0-9.]*\)x less; the first [0-9.]* MB, then \([0-9.]*\) MB a frame)'
  for wall in default 4x3; do
    for scene in mesh swap picture still movie; do
      log=$out/bytes-$wall-$scene.txt
      # shellcheck disable=SC2086
      "${local_mpirun[@]}" -np "${np[$wall]}" "$l2wall" run ${wall_arg[$wall]} ${scene_args[$scene]} \
        --mpi --link-codec zstd --path both --frames "$frames" --refresh 0 --keep none --no-progress \
        --out "$out/run-bytes" >"$log"
      dvi=$(field "$log" "s/^network: $sent of DVI frames.*/\\2,\\1,\\3,\\4/p")
      tiles=$(field "$log" "s/^network: $sent of tiles.*/\\2,\\1,\\3,\\4/p")
      echo "$wall,$scene,$dvi,$tiles" | tee -a "$out/bytes.csv"
    done
  done
fi

if [[ $only == fps || -z $only ]]; then
  echo "wall,where,link,codec,fps" >"$out/fps.csv"
  for wall in default 4x3; do
    n=$frames
    [[ $wall == 4x3 ]] && n=$((frames / 2))
    args=(run ${wall_arg[$wall]} --frames "$n" --refresh 0 --keep none --no-progress)
    "$l2wall" "${args[@]}" --out "$out/run-fps" >"$out/fps-$wall-one.txt"
    echo "$wall,one machine,,,$(fps_of "$out/fps-$wall-one.txt")" | tee -a "$out/fps.csv"
    "${local_mpirun[@]}" -np "${np[$wall]}" "$l2wall" "${args[@]}" --mpi --out "$out/run-fps" \
      >"$out/fps-$wall-loopback.txt"
    echo "$wall,MPI loopback,,auto (whole),$(fps_of "$out/fps-$wall-loopback.txt")" | tee -a "$out/fps.csv"
    for rate in unshaped 10gbit 1gbit; do
      # "both": the DVI and the vizserver path at once (the vizserver path runs over MPI only
      # beside the DVI path), tiles and frames as changes.
      for codec in zstd whole both; do
        log=$out/fps-$wall-$rate-$codec.txt
        shaping=() how=(--link-codec "$codec")
        [[ $rate != unshaped ]] && shaping=(--rate "$rate")
        [[ $codec == both ]] && how=(--link-codec zstd --path both)
        bash "$root/scripts/cluster.sh" --hosts "${hosts[$wall]}" "${shaping[@]}" -- "$l2wall" \
          "${args[@]}" --mpi "${how[@]}" --out "$out/run-fps" >"$log" 2>&1
        echo "$wall,cluster,$rate,$codec,$(fps_of "$log")" | tee -a "$out/fps.csv"
      done
    done
  done
fi
if [[ $only != bytes ]] && command -v gnuplot >/dev/null; then
    # x: 1 = 1 Gbit/s, 2 = 10 Gbit/s, 3 = unshaped; one line per wall and codec.
    for wall in default 4x3; do
      for codec in zstd whole both; do
        awk -F, -v w="$wall" -v c="$codec" '$1==w && $2=="cluster" && $4==c {
          x = $3=="1gbit" ? 1 : $3=="10gbit" ? 2 : 3; print x, $5 }' "$out/fps.csv" | sort -n \
          >"$out/plot-$wall-$codec.dat"
      done
      awk -F, -v w="$wall" '$1==w && $2=="one machine" { print 1, $5; print 3, $5 }' \
        "$out/fps.csv" >"$out/plot-$wall-one.dat"
    done
    gnuplot <<GP
set terminal pngcairo size 1000,440 font "DejaVu Sans,10"
set output "$out/network.png"
set multiplot layout 1,2 title "The wall across hosts (network namespaces), mesh scene, --refresh 0: frames/s against each link's rate"
set xrange [0.7:3.3]
set xtics ("1 Gbit/s" 1, "10 Gbit/s" 2, "unshaped" 3)
set ylabel "frames/s"
set yrange [0:*]
set key bottom right
set grid ytics
set title "default wall: 4 pipeservers, 1 column, 3 hosts"
plot "$out/plot-default-zstd.dat" with linespoints lw 2 title "as changes (zstd)", \
     "$out/plot-default-whole.dat" with linespoints lw 2 dt 2 title "whole frames", \
     "$out/plot-default-both.dat" with linespoints lw 2 dt 4 title "both paths, as changes", \
     "$out/plot-default-one.dat" with lines lc rgb "gray" dt 3 title "one machine, no MPI"
set title "4x3 monitor wall: 8 pipeservers, 2 columns, 4 hosts"
plot "$out/plot-4x3-zstd.dat" with linespoints lw 2 title "as changes (zstd)", \
     "$out/plot-4x3-whole.dat" with linespoints lw 2 dt 2 title "whole frames", \
     "$out/plot-4x3-both.dat" with linespoints lw 2 dt 4 title "both paths, as changes", \
     "$out/plot-4x3-one.dat" with lines lc rgb "gray" dt 3 title "one machine, no MPI"
unset multiplot
GP
    echo "plot: $out/network.png"
  fi
