#!/usr/bin/env bash
# A long live run at full speed, watched from outside: every few seconds the resident memory
# (VmRSS) and open descriptors of every process of the run, so a leak shows as growth. On one
# machine: l2wall and pipeserver 0. With --cluster: the run across three namespace hosts
# (scripts/cluster.sh, its default hosts: the coordinator and pipeservers 0-1 on render-a,
# pipeservers 2-3 on render-b, the board column on display-a), `l2wall run --mpi`, and every rank.
# Writes OUT/soak.csv (seconds, frames logged by pipeserver 0, process, KB, fds: one row per
# process per sample) and prints, per process, its second and last sample and the growth.
#
#   scripts/soak.sh [--frames N] [--every SECONDS] [--out DIR] [--build DIR] [--cluster] [-- L2WALL-RUN-ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=20000 every=5 out=$root/build/soak build=$root/build/default extra=() cluster=0
usage() { sed -n '/^#   scripts/p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --frames) frames=${2:?}; shift 2 ;;
    --every) every=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --build) build=${2:?}; shift 2 ;;
    --cluster) cluster=1; shift ;;
    -h | --help) usage; exit 0 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "soak.sh: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done
rm -rf "$out" && mkdir -p "$out"
run_args=(run --frames "$frames" --refresh 0 --keep none --no-progress --out "$out/run" "${extra[@]}")
if ((cluster)); then
  bash "$root/scripts/cluster.sh" -- "$build/l2wall/l2wall" "${run_args[@]}" --mpi \
    >"$out/run.txt" 2>&1 &
else
  "$build/l2wall/l2wall" "${run_args[@]}" >"$out/run.txt" 2>&1 &
fi
run=$!
trap 'kill $run 2>/dev/null || true' EXIT
rss() { awk '/^VmRSS/ {print $2}' "/proc/$1/status" 2>/dev/null || echo; }
fds() { ls "/proc/$1/fd" 2>/dev/null | wc -l; }
# The processes watched, one "PID NAME" a line. One machine: l2wall and pipeserver 0. A cluster:
# every rank (l2wall, or the pipeserver it became), named by its rank from its environment.
watched() {
  if ((!cluster)); then
    echo "$run l2wall"
    local p0
    p0=$(pgrep -f -- "--pipeserver 0 .*$out/run" | head -1 || true)
    [[ -z $p0 ]] || echo "$p0 pipeserver-0"
    return
  fi
  local pid comm rank
  for pid in $(pgrep -f -- "$out/run" || true); do
    comm=$(cat "/proc/$pid/comm" 2>/dev/null || true)
    [[ $comm == l2wall || $comm == pipeserver ]] || continue
    rank=$(tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')
    [[ -n $rank ]] && echo "$pid rank-$rank-$comm"
  done
}
echo "seconds,frames,process,kb,fds" >"$out/soak.csv"
start=$SECONDS
while kill -0 "$run" 2>/dev/null; do
  # grep -c prints 0 and fails where no line matches: the count once, never "0" twice.
  done_frames=$(grep -c '^frame ' "$out/run/pipeserver-0.log" 2>/dev/null) || done_frames=0
  while read -r pid name; do
    kb=$(rss "$pid")
    [[ -n $kb ]] && echo "$((SECONDS - start)),$done_frames,$name,$kb,$(fds "$pid")" >>"$out/soak.csv"
  done < <(watched)
  sleep "$every"
done
status=0
wait "$run" || status=$?
trap - EXIT
grep "^l2wall run:" "$out/run.txt" || tail -n 3 "$out/run.txt"
# Per process, from its second sample (the first may be taken while the run still starts) to
# its last.
awk -F, 'NR > 1 {
    n[$3]++
    if (n[$3] == 2) { t0[$3] = $1; f0[$3] = $2; k0[$3] = $4; d0[$3] = $5 }
    t1[$3] = $1; f1[$3] = $2; k1[$3] = $4; d1[$3] = $5
  } END {
    bad = 0
    for (p in n) {
      if (n[p] < 3) { printf "%s: only %d samples\n", p, n[p]; bad = 1; continue }
      printf "%s: from %s s (frame %s) to %s s (frame %s): %s -> %s KB (%+d), %s -> %s fds\n",
        p, t0[p], f0[p], t1[p], f1[p], k0[p], k1[p], k1[p] - k0[p], d0[p], d1[p]
    }
    exit bad
  }' "$out/soak.csv" | sort || { echo "soak.sh: too few samples: a longer run (--frames)"; exit 1; }
echo "samples: $out/soak.csv; the run exited with $status"
exit "$status"
