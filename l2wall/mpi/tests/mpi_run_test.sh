#!/usr/bin/env bash
# A wall over real mpirun ranks against the same wall on one machine: every display of the
# last frame must be the same bytes. The TCP transport is forced (mpirun_local.sh), so the
# frames really cross sockets. Usage: mpi_run_test.sh L2WALL OUT NP PATH [WALL [CODEC]] (PATH dvi
# or both; no WALL: the built-in default wall; CODEC: --link-codec of the MPI run, default auto,
# which on one machine sends frames whole). Also: swap lock held in every refresh, and the
# wrong -np is refused in one line naming the numbers. With PATH both, each run compares its
# DVI and vizserver displays (--compare), the MPI run's vizserver displays must be the
# one-machine run's too, and (on the default wall, the cheaper) a mismatch injected under MPI
# must fail the run. No warning of busy-polling ranks (mpirun_local.sh yields); on the default
# wall's DVI path, a hostfile promising more slots than cores, without that option, gets the
# warning once where the ranks outnumber the cores.
set -euo pipefail
l2wall=$1 out=$2 np=$3 path=$4 wall=${5:+--wall $5} codec=${6:-auto}
frames=10
source "$(dirname "$0")/mpirun_local.sh"  # mpirun_local: mpirun on loopback only; mpirun_wait
mpirun=("${mpirun_local[@]}")
rm -rf "$out" && mkdir -p "$out"
paths=(--path "$path")
[[ $path == both ]] && paths+=(--compare)

start=$(date +%s%N)
"$l2wall" run $wall "${paths[@]}" --frames $frames --refresh 0 --out "$out/one" \
  --no-progress >/dev/null
one_done=$(date +%s%N)
"${mpirun[@]}" -np "$np" "$l2wall" run $wall --mpi --link-codec "$codec" "${paths[@]}" --frames $frames --refresh 0 \
  --out "$out/mpi" --no-progress >"$out/mpi.txt" 2>"$out/mpi.err" &
mpirun_wait $! || { echo "FAIL: the MPI run failed:"; cat "$out/mpi.err"; exit 1; }
mpi_done=$(date +%s%N)
cat "$out/mpi.err" >&2
if grep "busy-poll" "$out/mpi.err"; then echo "FAIL: a busy-polling warning, yet mpirun yields"; exit 1; fi
echo "one machine $(((one_done - start) / 1000000)) ms, MPI $(((mpi_done - one_done) / 1000000)) ms"

shopt -s nullglob
pictures=("$out"/one/frame-$((frames - 1))/display-*.png)  # -vizserver.png too, with both
[[ ${#pictures[@]} -gt 0 ]] || { echo "FAIL: the one-machine run wrote no displays"; exit 1; }
for p in "${pictures[@]}"; do
  m="$out/mpi/frame-$((frames - 1))/$(basename "$p")"
  cmp "$p" "$m" || { echo "FAIL: $m differs from $p"; exit 1; }
done
grep -q "^l2wall run: $frames frames" "$out/mpi.txt" || { echo "FAIL: no summary"; exit 1; }
# The coordinator checked swap lock in every refresh (a violation would have failed the run).
grep -E "^swap lock: every display of each of [0-9]+ group\(s\) showed the same frame in all [1-9][0-9]* refreshes" \
  "$out/mpi.txt" || { echo "FAIL: no swap-lock line"; cat "$out/mpi.txt"; exit 1; }
echo "same bytes: ${#pictures[@]} display pictures of frame $((frames - 1))"

if [[ $path == both ]]; then
  grep -E "^compare: [0-9]+ display pictures identical byte for byte" "$out/mpi.txt" ||
    { echo "FAIL: the MPI run compared nothing"; exit 1; }
fi
if [[ $path == both && -z $wall ]]; then
  "${mpirun[@]}" -np "$np" "$l2wall" run --mpi "${paths[@]}" --inject-mismatch 3 \
    --frames 5 --out "$out/mismatch" --no-progress >/dev/null 2>"$out/mismatch.txt" &
  if mpirun_wait $!; then
    echo "FAIL: an injected mismatch passed under MPI"
    exit 1
  fi
  grep -E "^l2wall: frame 3: display 0 differs between the DVI and vizserver paths in 1 pixels" \
    "$out/mismatch.txt" || { echo "FAIL: no mismatch line"; cat "$out/mismatch.txt"; exit 1; }
fi

# One rank short: refused before anything runs, in one line with the numbers.
"${mpirun[@]}" -np $((np - 1)) "$l2wall" run $wall --mpi --frames 1 --out "$out/short" \
  2>"$out/short.txt" >/dev/null &
if mpirun_wait $!; then
  echo "FAIL: -np $((np - 1)) was accepted"
  exit 1
fi
grep -qE "^l2wall: --mpi: this wall needs mpirun -np $np \(1 coordinator \+ [0-9]+ pipeservers? \+ [0-9]+ board columns?\), got $((np - 1)) ranks$" \
  "$out/short.txt" || { echo "FAIL: no one-line -np error:"; cat "$out/short.txt"; exit 1; }
echo "-np $((np - 1)) refused"

# A hostfile with more slots than cores (`localhost slots=64`): Open MPI sees no oversubscription
# and busy-polls unless told; the coordinator says so in one line at the start.
if [[ $path == dvi && -z $wall ]]; then
  echo "localhost slots=64" >"$out/hosts"
  "${mpirun_loopback[@]}" --hostfile "$out/hosts" -np "$np" "$l2wall" run --mpi --frames 2 \
    --out "$out/busy" --no-progress >/dev/null 2>"$out/busy.err" &
  mpirun_wait $! || { echo "FAIL: the run on the hostfile failed:"; cat "$out/busy.err"; exit 1; }
  cores=$(getconf _NPROCESSORS_ONLN)
  want=$((np > cores ? 1 : 0))
  got=$(grep -c "^l2wall: --mpi: $np ranks on $(hostname), which has $cores cores\?, busy-poll while they wait (Open MPI's mpi_yield_when_idle is off), which can make the run several times slower: add --mca mpi_yield_when_idle 1 to mpirun$" \
    "$out/busy.err" || true)
  ((got == want)) ||
    { echo "FAIL: $got busy-polling warnings for $np ranks on $cores cores, want $want:"; cat "$out/busy.err"; exit 1; }
  echo "busy-polling: $got warning(s) for $np ranks on $cores cores without mpi_yield_when_idle"
  grep "busy-poll" "$out/busy.err" || true
fi
