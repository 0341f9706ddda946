#!/usr/bin/env bash
# The control page under MPI: the coordinator serves it, the displays' pictures come from the
# board column ranks, a pause longer than the pipeservers' READY patience holds the run without
# ending it (they are started to ask with SYNC? for as long as a person pauses), and a stop is
# refused with its reason (remote ranks cannot be ended early). Usage: mpi_page_test.sh L2WALL OUT
set -euo pipefail
l2wall=$1 out=$2
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
rm -rf "$out" && mkdir -p "$out"
frames=150
"${mpirun_local[@]}" -np 6 "$l2wall" run --mpi --frames $frames --keep none --out "$out/run" \
  --no-progress --http 127.0.0.1:0 >"$out/run.txt" 2>"$out/run.err" &
run=$!
trap 'kill $run 2>/dev/null || true; mpirun_base_remove' EXIT

fail() { echo "FAIL: $*"; cat "$out/run.err"; exit 1; }
# Waits (at most 60 s) until the jq filter $1 is true of the state.
state() { curl -s -m 10 "$base/api/state"; }
wait_state() {
  for _ in $(seq 600); do
    [[ $(state | jq "$1") == true ]] && return 0
    kill -0 $run 2>/dev/null || fail "the run ended while waiting for $1"
    sleep 0.1
  done
  fail "the state never got $1: $(state)"
}
frame() { state | jq .frame; }

for _ in $(seq 600); do grep -q "control page: http" "$out/run.err" && break; sleep 0.1; done
url=$(grep -o 'http://127\.0\.0\.1:[0-9]*/?token=[0-9a-f]*' "$out/run.err") || fail "no URL printed"
base=${url%%/\?token=*}
token=${url##*token=}
wait_state '.frame >= 3'
curl -s -m 10 -o "$out/display-0.png" "$base/api/display/0.png"
[[ $(head -c 4 "$out/display-0.png" | od -An -c | tr -d ' ') == "211PNG" ]] ||
  fail "display 0 is not a PNG picture from the column rank"

curl -s -m 10 -d '' "$base/api/pause?token=$token" >/dev/null
wait_state '.paused'
held=$(frame)
sleep 6  # longer than a pipeserver's default patience: 3 SYNC? retries of 1000 ms
[[ $(frame) == "$held" ]] || fail "frames went on while paused: $held, then $(frame)"
# The answer is the run's refusal, with the reason its events list too.
code=$(curl -s -m 10 -o "$out/stop.json" -w '%{http_code}' -d '' "$base/api/stop?token=$token")
[[ $code == 409 ]] || fail "stop under --mpi answered $code: $(cat "$out/stop.json")"
jq -e '.error | startswith("not stopped: the pipeserver ranks cannot be ended early under --mpi")' \
  "$out/stop.json" >/dev/null || fail "stop under --mpi: $(cat "$out/stop.json")"
wait_state '[.events[].text] | any(startswith("not stopped: the pipeserver ranks cannot be ended early under --mpi"))'
[[ $(state | jq .stoppable) == false ]] || fail "the page offers Stop under --mpi"
curl -s -m 10 -d '' "$base/api/resume?token=$token" >/dev/null

mpirun_wait $run || fail "the MPI run failed after the pause"
trap mpirun_base_remove EXIT
grep -q "^l2wall run: $frames frames" "$out/run/summary.txt" || fail "not every frame: $(head -1 "$out/run/summary.txt")"
grep -q "control page: 1 pause, 0 saves" "$out/run/summary.txt" || fail "summary: $(cat "$out/run/summary.txt")"
if grep -q "no READY" "$out/run.err"; then fail "a pipeserver gave up during the pause"; fi
echo "ok: paused at frame $held for 6 s under MPI, $frames frames in the end"
