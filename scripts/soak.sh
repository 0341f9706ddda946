#!/usr/bin/env bash
# A long live run at full speed, watched from outside: every few seconds the resident memory
# (VmRSS) and open descriptors of l2wall and of pipeserver 0, so a leak shows as growth.
# Writes OUT/soak.csv (seconds, frames logged by pipeserver 0, then per process KB and fds) and
# prints the first and last sample and the growth of each.
#
#   scripts/soak.sh [--frames N] [--every SECONDS] [--out DIR] [--build DIR] [-- L2WALL-RUN-ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=20000 every=5 out=$root/build/soak build=$root/build/default extra=()
usage() { sed -n '/^#   scripts/p' "$0" | sed 's/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --frames) frames=${2:?}; shift 2 ;;
    --every) every=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --build) build=${2:?}; shift 2 ;;
    -h | --help) usage; exit 0 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "soak.sh: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done
rm -rf "$out" && mkdir -p "$out"
"$build/l2wall/l2wall" run --frames "$frames" --refresh 0 --keep none --no-progress \
  --out "$out/run" "${extra[@]}" >"$out/run.txt" 2>&1 &
run=$!
trap 'kill $run 2>/dev/null || true' EXIT
rss() { awk '/^VmRSS/ {print $2}' "/proc/$1/status" 2>/dev/null || echo; }
fds() { ls "/proc/$1/fd" 2>/dev/null | wc -l; }
echo "seconds,frames,l2wall_kb,l2wall_fds,pipeserver0_kb,pipeserver0_fds" >"$out/soak.csv"
start=$SECONDS ps0=
while kill -0 "$run" 2>/dev/null; do
  [[ -n $ps0 ]] || ps0=$(pgrep -f -- "--pipeserver 0 .*$out/run" | head -1 || true)
  if [[ -n $ps0 ]] && [[ -e /proc/$ps0 ]]; then
    done_frames=$(grep -c '^frame ' "$out/run/pipeserver-0.log" 2>/dev/null || echo 0)
    echo "$((SECONDS - start)),$done_frames,$(rss $run),$(fds $run),$(rss "$ps0"),$(fds "$ps0")" >>"$out/soak.csv"
  fi
  sleep "$every"
done
status=0
wait "$run" || status=$?
trap - EXIT
grep "^l2wall run:" "$out/run.txt" || tail -n 3 "$out/run.txt"
samples=$(($(wc -l <"$out/soak.csv") - 1))
if ((samples < 3)); then echo "soak.sh: only $samples samples: a longer run (--frames)"; exit 1; fi
# Growth from the second sample (the first may be taken while the run still starts) to the last.
awk -F, 'NR == 3 { for (i = 1; i <= NF; ++i) a[i] = $i } END {
  printf "from %s s (frame %s) to %s s (frame %s): l2wall %s -> %s KB, %s -> %s fds; pipeserver 0 %s -> %s KB, %s -> %s fds\n",
    a[1], a[2], $1, $2, a[3], $3, a[4], $4, a[5], $5, a[6], $6 }' "$out/soak.csv"
echo "samples: $out/soak.csv; the run exited with $status"
exit "$status"
