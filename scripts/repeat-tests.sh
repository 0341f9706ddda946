#!/usr/bin/env bash
# The three test phases of scripts/test.sh, N times over: builds what each needs once (release:
# everything; ASan+UBSan and TSan: the executables their tests need), then runs the release
# (default), the ASan and the TSan ctest phase N times each, and counts failures per test and
# phase. A test that fails once in N is a flake to fix, not to re-run. After each phase it lists
# what the phase left behind (new since the phase began, named with round and phase): Open MPI
# session folders (/tmp/ompi.<host>.<uid>, the MPI tests' own bases /tmp/l2mpi.*, and the job
# folders in them) and our shared memory (/dev/shm/l2-*); a passing test must leave neither.
# The phase's logs are then kept too (ctest's, and every test's whole output).
#
# --load  loads the machine as CI does, for the whole run: beside the tests, a compile at the
#         idle scheduling priority (SCHED_IDLE, as scripts/test.sh's builds beside the tests) —
#         a clean build of the fuzz harnesses (the fuzz preset's l2_fuzzers, as test.sh
#         builds them) in a scratch folder (build/repeat-load), over and over, ended with the
#         run. Its output: build/repeat-load.log.
#
# Usage: scripts/repeat-tests.sh [--load] N
set -euo pipefail
cd "$(dirname "$0")/.."
usage() { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; }
load=0
while (($#)); do
  case $1 in
    --load) load=1; shift ;;
    -h | --help) usage; exit 0 ;;
    -*) echo "repeat-tests.sh: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) break ;;
  esac
done
(($# == 1)) || { echo "repeat-tests.sh: one N expected" >&2; usage >&2; exit 2; }
rounds=$1
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "repeat-tests.sh: N must be a positive integer, got '$rounds'" >&2; exit 2; }

phases=(default asan tsan)
declare -A target=([default]=all [asan]=l2_asan_tests [tsan]=l2_tsan_tests)
jobs=$(nproc)
start=$SECONDS
for preset in "${phases[@]}"; do
  echo "=== $preset: build (${target[$preset]})"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs" --target "${target[$preset]}" -- --quiet
done

# The load: its own process group (setsid), so that ending it ends the compiler under it.
idle=(chrt --idle 0)
"${idle[@]}" true 2>/dev/null || idle=(nice -n 19)
load_pid=
load_dir=build/repeat-load
logs=$(mktemp -d)
trap '[[ -z $load_pid ]] || kill -- -"$load_pid" 2>/dev/null || true; rm -rf "$logs"' EXIT
if ((load)); then
  echo "=== load: a clean build of l2_fuzzers in $load_dir, over and over, at ${idle[*]}"
  setsid "${idle[@]}" bash -c "set -euo pipefail
    cmake --preset fuzz -B '$load_dir' >/dev/null
    for ((n = 1; ; ++n)); do
      cmake --build '$load_dir' --target clean >/dev/null
      cmake --build '$load_dir' -j $jobs --target l2_fuzzers -- --quiet
      echo \"load build \$n finished\"
    done" >build/repeat-load.log 2>&1 &
  load_pid=$!
fi
# A load build that failed would leave the tests on an idle machine: that ends the run.
load_alive() {
  if ((!load)) || kill -0 "$load_pid" 2>/dev/null; then return; fi
  cat build/repeat-load.log
  echo "=== load: the build beside the tests ended (above): the rounds would not be under load"
  exit 1
}

# What a test can leave behind, one path a line: mpirun's session folders and the job folders
# in them (in /tmp, or in a test's own base /tmp/l2mpi.*), and our shared-memory segments.
# Another user's runs on the machine may show up too: each line is a lead to follow, not a
# verdict.
leftover_paths() {
  find /tmp -maxdepth 2 \( -path '/tmp/ompi.*' -o -path '/tmp/l2mpi.*' \) 2>/dev/null || true
  find /dev/shm -maxdepth 1 -name 'l2-*' 2>/dev/null || true
}
# keep_logs ROUND PRESET LOG: keeps the phase's ctest log and every test's whole output (ctest's
# LastTest.log, which the next phase's run replaces) as build/PRESET/repeat-round-ROUND[-tests].log.
keep_logs() {
  cp "$3" "build/$2/repeat-round-$1.log"
  cp "build/$2/Testing/Temporary/LastTest.log" "build/$2/repeat-round-$1-tests.log" 2>/dev/null || true
}
# leftovers_since BEFORE ROUND PRESET LOG: says each path new since the listing BEFORE (a file),
# with its time, and keeps the phase's logs; adds them to `leftovers`.
leftovers=()
leftovers_since() {
  local path line new
  new=$(comm -13 "$1" <(leftover_paths | sort))
  [[ -n $new ]] || return 0
  while read -r path; do
    line="round $2, $3: $path ($(date -r "$path" +%T 2>/dev/null || echo gone))"
    echo "=== left behind: $line"
    leftovers+=("$line")
  done <<<"$new"
  keep_logs "$2" "$3" "$4"
}

declare -A failures=() phase_seconds=()
failed_rounds=0
for ((round = 1; round <= rounds; round++)); do
  t0=$SECONDS
  round_failed=0
  times=
  failed_here=
  for preset in "${phases[@]}"; do
    log="$logs/$preset-$round.log"
    p0=$SECONDS
    leftover_paths | sort >"$logs/before"
    if ! ctest --preset "$preset" -j "$jobs" >"$log" 2>&1; then
      round_failed=1
      keep_logs "$round" "$preset" "$log"
    fi
    times+="$preset $((SECONDS - p0)) s, "
    phase_seconds[$preset]=$((${phase_seconds[$preset]:-0} + SECONDS - p0))
    # ctest's summary lists each failed test as "  <n> - <name> (Failed)".
    while read -r name; do
      failures["$preset $name"]=$((${failures["$preset $name"]:-0} + 1))
      failed_here+=" $preset:$name"
    done < <(sed -n 's/^[[:space:]]*[0-9]\+ - \([^ ]*\) (.*)$/\1/p' "$log")
    leftovers_since "$logs/before" "$round" "$preset" "$log"
    load_alive
  done
  failed_rounds=$((failed_rounds + round_failed))
  echo "=== round $round of $rounds: $((SECONDS - t0)) s (${times%, }), $([[ $round_failed = 0 ]] && echo passed || echo "FAILED:$failed_here")"
done
if ((load)); then
  echo "=== load: $(grep -c '^load build .* finished' build/repeat-load.log || true) clean builds of l2_fuzzers finished beside the tests"
fi

echo "=== failures per test over $rounds rounds$( ((load)) && echo " under load"):"
if [[ ${#failures[@]} -eq 0 ]]; then
  echo "none"
else
  for key in "${!failures[@]}"; do echo "${failures[$key]} $key"; done | sort -rn
  echo "(the logs of each failed round: build/<preset>/repeat-round-<n>.log, and -tests.log: every test's output)"
fi
if [[ ${#leftovers[@]} -eq 0 ]]; then
  echo "=== leftovers: none"
else
  echo "=== leftovers: ${#leftovers[@]} (the log of each such phase: build/<preset>/repeat-round-<n>.log)"
  printf '%s\n' "${leftovers[@]}"
fi
totals=
for preset in "${phases[@]}"; do totals+="$preset ${phase_seconds[$preset]} s, "; done
echo "=== time per phase over the $rounds rounds: ${totals%, }"
echo "=== $rounds rounds in $((SECONDS - start)) s (build included)"
[[ $failed_rounds -eq 0 ]]
