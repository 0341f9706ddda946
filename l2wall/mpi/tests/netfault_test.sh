#!/usr/bin/env bash
# The wall across hosts whose network fails (scripts/cluster.sh: network namespaces joined by a
# bridge, mpirun across them), the default wall over render-a (coordinator, pipeservers 0-1),
# render-b (pipeservers 2-3) and display-a (the board column):
#   a. 1 % of the packets dropped at random on every host's link, both ways (--loss 1), and every
#      packet held 5 ms ± 5 ms (--delay 5 --jitter 5: the link emulator, as netem would): both
#      paths, their displays the one-machine run's bytes, swap lock every refresh;
#   b. render-b's link cut mid-run (every packet dropped, no connection told): the coordinator
#      names a pipeserver on render-b and what it lost within the liveness timeout (a ceiling of
#      10x), the run exits non-zero, and once the link is back nothing is left on any host;
#   c. render-b's link cut for 1 s, well under the liveness timeout, and restored: the run goes
#      on and finishes with the one-machine run's bytes;
#   d. --survive-host-loss under an mpirun that keeps the job, pipeserver 2 alone on render-b
#      (the wall has room for one loss): its link cut, the run goes on without it, says so and
#      renders every frame; nothing left once the link is back.
# Before them, a bad --loss, --delay, --jitter, --id or --link is refused in one line.
# Exit 77 (skipped) where this machine cannot make network namespaces or has no nft.
# Usage: netfault_test.sh L2WALL OUT CLUSTER_SH LINK_EMULATOR
set -euo pipefail
l2wall=$1 out=$2 cluster=$3 emulator=$4
rm -rf "$out" && mkdir -p "$out"
command -v nft >/dev/null || { echo "no nft (apt-get install nftables): skipped"; exit 77; }
source "$(dirname "$0")/rank_pid.sh"
source "$(dirname "$0")/cluster_left.sh"  # nothing_left

# refused CODE LINE ARGS...: cluster.sh ARGS exits CODE with LINE on stderr, making nothing.
refused() {
  local code=$1 line=$2 status=0 err
  shift 2
  err=$(bash "$cluster" "$@" 2>&1 >/dev/null) || status=$?
  [[ $status == "$code" && $err == "$line" ]] ||
    { echo "FAIL: cluster.sh $*: exit $status, '$err'; wanted $code, '$line'"; exit 1; }
}
for p in 0 0.0 100 1.55 -1 abc; do
  refused 2 "cluster.sh: --loss '$p' is not a percentage above 0 and below 100 (one decimal at most)" \
    --loss "$p" -- true
done
for d in 0 0.000 abc 1e3 10001 5.0001; do
  refused 2 "cluster.sh: --delay '$d' is not milliseconds above 0 and at most 10000 (e.g. 5, 0.5)" \
    --delay "$d" -- true
done
refused 2 "cluster.sh: --jitter '-1' is not milliseconds from 0 to 10000 (e.g. 5, 0.5)" --delay 5 --jitter -1 -- true
refused 2 "cluster.sh: --jitter needs --delay (the jitter is around the delay)" --jitter 5 -- true
refused 2 "cluster.sh: --delay and --rate cannot be combined: the link emulator does not shape links" \
  --delay 5 --rate 1gbit -- true
refused 2 "cluster.sh: --delay needs the link emulator, not at $out/none (cmake --build --preset default, or --link-emulator PATH)" \
  --delay 5 --link-emulator "$out/none" -- true
# The emulator attaches to taps that exist; TUNSETIFF would quietly make one joined to nothing.
err=$("$emulator" --tap l2nonetap --delay 1 2>&1 >/dev/null) && status=0 || status=$?
[[ $status == 1 && $err == "link_emulator: tap 'l2nonetap': no such device (ip tuntap add dev l2nonetap mode tap)" ]] ||
  { echo "FAIL: link_emulator --tap l2nonetap: exit $status, '$err'"; exit 1; }
refused 2 "cluster.sh: --id 'Render' is not a-z then a-z or 0-9, 8 at most" --id Render -- true
refused 2 "cluster.sh --link: 'down' is not cut or restore" --link nfnone render-b down
refused 1 "cluster.sh --link: no host render-b in cluster nfnone (no namespace nfnone-render-b)" \
  --link nfnone render-b cut
echo "cluster.sh refuses a bad --loss, --delay, --jitter, --id and --link in one line, the link emulator a tap that is not there"

# same_displays ONE MPI FRAME: every display picture of FRAME of ONE is in MPI, byte for byte.
same_displays() {
  local p n=0
  for p in "$1/frame-$3"/display-*.png; do
    cmp "$p" "$2/frame-$3/$(basename "$p")" || { echo "FAIL: $2 differs"; exit 1; }
    n=$((n + 1))
  done
  ((n > 0)) || { echo "FAIL: $1 has no displays"; exit 1; }
  echo "  $n display pictures of frame $3 the same bytes as on one machine"
}

# a. 1 % loss and 5 ms ± 5 ms on every link, both paths: TCP under that loss and reordering
# carries the vizserver path's whole tiles slowly, so fewer frames than the other cases.
frames=12
"$l2wall" run --path both --compare --frames $frames --refresh 0 --out "$out/one" --no-progress >/dev/null
status=0
bash "$cluster" --loss 1 --delay 5 --jitter 5 --link-emulator "$emulator" -- \
  "$l2wall" run --mpi --path both --compare --frames $frames --refresh 0 \
  --out "$out/lossy" --no-progress >"$out/lossy.txt" 2>"$out/lossy.err" || status=$?
if ((status == 77)); then cat "$out/lossy.err"; exit 77; fi
((status == 0)) || { echo "FAIL: --loss 1 --delay 5 --jitter 5: exit $status"; cat "$out/lossy.err"; exit 1; }
grep -qE "^compare: [0-9]+ display pictures identical byte for byte" "$out/lossy.txt" ||
  { echo "FAIL: lossy, late links: no compare line"; cat "$out/lossy.txt"; exit 1; }
grep -E "^swap lock: every display of each of [0-9]+ group\(s\) showed the same frame in all [0-9]+ refreshes" \
  "$out/lossy.txt" || { echo "FAIL: lossy, late links: no swap-lock line"; cat "$out/lossy.txt"; exit 1; }
dropped=$(sed -n 's/^cluster: --loss 1: the hosts.* links dropped \([0-9]*\) of [0-9]* packets$/\1/p' "$out/lossy.txt")
((${dropped:-0} > 0)) || { echo "FAIL: --loss 1 dropped no packet"; tail -3 "$out/lossy.txt"; exit 1; }
echo "1 % loss on every link: $(grep '^cluster: --loss' "$out/lossy.txt")"
# The emulator's line: frames carried, and their mean hold. Each frame's hold is drawn from
# 0..10 ms and none leaves before its time, so a mean under 4 ms means frames were not held.
held=$(grep '^cluster: link_emulator: ' "$out/lossy.txt") ||
  { echo "FAIL: no line of the link emulator"; tail -3 "$out/lossy.txt"; exit 1; }
[[ $held =~ ^cluster:\ link_emulator:\ ([0-9]+)\ frames\ .*\ each\ held\ 5\ ±\ 5\ ms:\ held\ [0-9.]+\ to\ [0-9.]+\ ms,\ mean\ ([0-9]+)\.[0-9]+\ ms\;\ dropped\ 0\ past ]] ||
  { echo "FAIL: the link emulator's line is not as expected: $held"; exit 1; }
((BASH_REMATCH[1] > 1000 && BASH_REMATCH[2] >= 4)) ||
  { echo "FAIL: the link emulator carried too little or held too briefly: $held"; exit 1; }
[[ $held != *"went away"* ]] || { echo "FAIL: a tap went away mid-run: $held"; exit 1; }
echo "every packet held 5 ± 5 ms: $held"
same_displays "$out/one" "$out/lossy" $((frames - 1))


# under_way DIR FRAMES: until the pipeservers' reports hold FRAMES frames in all.
under_way() {
  for _ in $(seq 1200); do
    [[ $(cat "$1"/pipeserver-*.log 2>/dev/null | grep -c '^frame ') -ge $2 ]] && return
    sleep 0.05
  done
  echo "FAIL: the run in $1 did not get under way"
  exit 1
}

# ended_within RUN SECONDS: waits for the background job RUN, failing past SECONDS; sets status.
ended_within() {
  local run=$1
  for _ in $(seq $(($2 * 10))); do
    kill -0 "$run" 2>/dev/null || break
    sleep 0.1
  done
  kill -0 "$run" 2>/dev/null && { echo "FAIL: the run did not end within $2 s"; kill "$run"; exit 1; }
  status=0
  wait "$run" || status=$?
}

id=nf$((RANDOM % 100000))

# b. render-b cut off mid-run (the liveness timeout its default, 3 s; the stall timeout far
# above it, so the silence, not a stall, names what was lost).
cut_off() {
  local dir=$out/cut run pids start line waited
  bash "$cluster" --id "$id" -- "$l2wall" run --mpi --frames 100000 --stall-timeout 60000 \
    --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  run=$!
  under_way "$dir" 10
  pids=$(pgrep -f -- "$dir" || true)
  start=$(date +%s%N)
  bash "$cluster" --link "$id" render-b cut
  for _ in $(seq 300); do  # 30 s: 10x the timeout
    line=$(grep -E "^l2wall: pipeserver [23] \(rank [34] on render-b, pid [0-9]+\) is lost \(no word for 3 s: its host's network may be down\) while the displays wait for frame [0-9]+" "$dir.err") && break
    kill -0 "$run" 2>/dev/null || break
    sleep 0.1
  done
  waited=$((($(date +%s%N) - start) / 1000000))
  bash "$cluster" --link "$id" render-b restore
  [[ -n $line ]] || { echo "FAIL: no line naming render-b's loss within 30 s:"; cat "$dir.err"; kill "$run"; exit 1; }
  # The silence counts from render-b's last pulse, up to 200 ms before the cut.
  ((waited >= 2500)) || { echo "FAIL: render-b named lost after $waited ms, before the timeout"; exit 1; }
  ended_within "$run" 60
  ((status != 0)) || { echo "FAIL: exit 0 after render-b was cut off"; exit 1; }
  echo "render-b cut off: named after $waited ms: $line"
  nothing_left "$dir" "$pids"
}
cut_off

# c. render-b's link down for 1 s, the liveness timeout 5 s: the run goes on, its frames whole.
frames=40
"$l2wall" run --frames $frames --refresh 10 --out "$out/one-slow" --no-progress >/dev/null
short_cut() {
  local dir=$out/short-cut run
  bash "$cluster" --id "$id" -- "$l2wall" run --mpi --frames $frames --refresh 10 \
    --liveness-timeout 5000 --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  run=$!
  under_way "$dir" 8
  bash "$cluster" --link "$id" render-b cut
  sleep 1
  bash "$cluster" --link "$id" render-b restore
  kill -0 "$run" 2>/dev/null || { echo "FAIL: the run ended before the link came back"; cat "$dir.err"; exit 1; }
  ended_within "$run" 120
  ((status == 0)) || { echo "FAIL: exit $status after a 1 s cut"; cat "$dir.err"; exit 1; }
  grep -q "^l2wall run: $frames frames on 4 displays" "$dir.out" ||
    { echo "FAIL: not every frame"; cat "$dir.out" "$dir.err"; exit 1; }
  echo "render-b's link down for 1 s: the run went on"
  same_displays "$out/one-slow" "$dir" $((frames - 1))
  nothing_left "$dir" ""
}
short_cut

survived() {
  local dir=$out/survived run line
  sed -e 's/framebuffer_width = 800/framebuffer_width = 1024/' \
    -e 's/framebuffer_height = 600/framebuffer_height = 768/' "$(dirname "$0")/../../../walls/kd-2x2.toml" \
    >"$out/roomy.toml"
  bash "$cluster" --keep-job --id "$id" --hosts render-a:3,render-b:1,render-c:1,display-a:1 -- \
    "$l2wall" run --mpi --wall "$out/roomy.toml" --balance strips --survive-host-loss --frames 100 \
    --refresh 0 --stall-timeout 60000 --out "$dir" --no-progress >"$dir.out" 2>"$dir.err" &
  run=$!
  under_way "$dir" 20
  bash "$cluster" --link "$id" render-b cut
  for _ in $(seq 300); do
    line=$(grep -E "^l2wall: pipeserver 2 \(rank 3 on render-b, pid [0-9]+\) is lost \(no word for 3 s: its host's network may be down\) .* the run goes on without it" "$dir.err") && break
    kill -0 "$run" 2>/dev/null || break
    sleep 0.1
  done
  bash "$cluster" --link "$id" render-b restore
  [[ -n $line ]] || { echo "FAIL: no line of render-b's loss survived:"; cat "$dir.err"; kill "$run"; exit 1; }
  ended_within "$run" 60
  # mpirun keeping the job exits 1 once l2wall ended it after a loss (cluster.sh --help).
  ((status == 1)) || { echo "FAIL: cluster.sh exited $status"; cat "$dir.err"; exit 1; }
  grep -q "^l2wall run: 100 frames on 4 displays" "$dir.out" ||
    { echo "FAIL: not every frame rendered"; cat "$dir.out" "$dir.err"; exit 1; }
  echo "render-b cut off, survived: $line"
  nothing_left "$dir" ""
}
survived
echo "nothing left running on any host"
