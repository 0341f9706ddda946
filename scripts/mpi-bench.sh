#!/usr/bin/env bash
# The wall over MPI ranks against the same wall on one machine: frames/s of each (same wall,
# scene and frames, the emulator at full speed: --refresh 0), their ratio, and the DVI path's
# bytes per frame on the network (each pipeserver's frame to every column it feeds, counted by
# the senders, on the wire and raw) and the vizserver path's (tiles only, to the columns owning
# their displays),
# with the link a real cluster would need for that wall at 60 Hz. mpirun uses the
# TCP transport (--mca btl self,tcp), so the frames cross sockets even on one machine. Without
# MPIRUN-ARGS it runs on this machine over loopback only; with them, name the interfaces there.
#
#   scripts/mpi-bench.sh [--wall FILE] [--frames N] [--scene NAME] [--out DIR] [--build DIR]
#                        [-- MPIRUN-ARGS...]   (e.g. -- --hostfile hosts
#                                                     --mca btl_tcp_if_include 10.0.0.0/24
#                                                     --mca oob_tcp_if_include 10.0.0.0/24)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
wall=
frames=60
scene=mesh
out=$root/build/mpi-bench
build=$root/build/default
usage() { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --wall) wall="--wall $2"; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) usage; exit 0 ;;
    --) shift; break ;;
    *) echo "mpi-bench.sh: unknown argument $1" >&2; usage >&2; exit 2 ;;
  esac
done
l2wall=$build/l2wall/l2wall
[[ -x $l2wall ]] || { echo "mpi-bench.sh: no $l2wall: build it first" >&2; exit 1; }
rm -rf "$out" && mkdir -p "$out"
# mpirun refuses root unless told; said here, for this script's runs only.
if [[ $(id -u) == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
# On one machine, loopback only: Open MPI otherwise takes every interface up when the job
# starts, and one that appears or goes away mid-run (a namespace's bridge) can hang it. On a
# cluster, the interfaces are the caller's to name among MPIRUN-ARGS.
# A waiting rank yields its core where the ranks outnumber them (README, "The wall across
# machines").
mpirun=(mpirun --oversubscribe --mca btl self,tcp)
if (($# == 0)); then
  mpirun+=(--mca btl_tcp_if_include lo --mca oob_tcp_if_include lo --mca mpi_yield_when_idle 1)
fi
args=(run $wall --scene "$scene" --frames "$frames" --refresh 0 --keep none --no-progress)
# The vizserver path's tiles are counted in a run of both paths of its own (not timed).
both=(run $wall --scene "$scene" --frames 10 --refresh 0 --keep none --no-progress --path both)

# The ranks the wall needs, from l2wall's own refusal of -np 1.
np=$( ("${mpirun[@]}" -np 1 "$l2wall" "${args[@]}" --mpi --out "$out/np" 2>&1 || true) |
       sed -n 's/^l2wall: --mpi: this wall needs mpirun -np \([0-9]*\) .*/\1/p')
[[ -n $np ]] || { echo "mpi-bench.sh: could not learn the rank count" >&2; exit 1; }

fps() { sed -n 's/^l2wall run: .*: \([0-9.]*\) fps.*/\1/p' "$1"; }
"$l2wall" "${args[@]}" --out "$out/one" >"$out/one.txt"
"${mpirun[@]}" "$@" -np "$np" \
  "$l2wall" "${args[@]}" --mpi --out "$out/mpi" >"$out/mpi.txt"
"${mpirun[@]}" "$@" -np "$np" \
  "$l2wall" "${both[@]}" --mpi --out "$out/both" >"$out/both.txt"
one=$(fps "$out/one.txt") mpi=$(fps "$out/mpi.txt")
# "network: X MB a frame on the wire (Y MB raw, ...) of DVI frames ...": X, and Y as raw_*.
wire() { sed -n "s/^network: \([0-9.]*\) MB a frame on the wire (\([0-9.]*\) MB raw.* of $2.*/\\$3/p" "$1"; }
mb=$(wire "$out/mpi.txt" "DVI frames" 1) raw_mb=$(wire "$out/mpi.txt" "DVI frames" 2)
tiles=$(wire "$out/both.txt" tiles 1) raw_tiles=$(wire "$out/both.txt" tiles 2)
kb=$(sed -n 's/.*; \([0-9.]*\) KB a frame of refresh records.*/\1/p' "$out/mpi.txt")
echo "wall: ${wall:-built-in default}, scene $scene, $frames frames, mpirun -np $np"
echo "one machine: $one fps"
echo "MPI (TCP):   $mpi fps ($(awk -v a="$mpi" -v b="$one" 'BEGIN{printf "%.2f", a/b}') x one machine)"
echo "network, DVI path: $mb MB per frame of frames on the wire ($raw_mb MB raw), $kb KB per frame of refresh records"
echo "network, vizserver path: $tiles MB per frame of tiles on the wire ($raw_tiles MB raw)"
echo "at 60 Hz: $(awk -v m="$mb" 'BEGIN{printf "%.1f", m*60*8/1000}') Gbit/s into the columns on the DVI path, $(awk -v m="$tiles" 'BEGIN{printf "%.1f", m*60*8/1000}') on the vizserver path"
