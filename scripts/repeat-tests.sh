#!/usr/bin/env bash
# The sanitizer phases of scripts/test.sh, N times over: builds the ASan and TSan test targets
# once, then runs the ASan and the TSan ctest phase N times each, and counts failures per test.
# A test that fails once in N is a flake to fix, not to re-run. Usage: scripts/repeat-tests.sh N
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:?usage: scripts/repeat-tests.sh N (rounds of the ASan and TSan phases)}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "repeat-tests.sh: N must be a positive integer, got '$rounds'" >&2; exit 2; }

jobs=$(nproc)
start=$SECONDS
for preset in asan tsan; do
  echo "=== $preset: build (l2_${preset}_tests)"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs" --target "l2_${preset}_tests" -- --quiet
done

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
declare -A failures=()
failed_rounds=0
for ((round = 1; round <= rounds; round++)); do
  t0=$SECONDS
  round_failed=0
  for preset in asan tsan; do
    log="$logs/$preset-$round.log"
    if ! ctest --preset "$preset" -j "$jobs" >"$log" 2>&1; then
      round_failed=1
      cp "$log" "build/$preset/repeat-round-$round.log"
    fi
    # ctest's summary lists each failed test as "  <n> - <name> (Failed)".
    while read -r name; do
      failures["$preset $name"]=$((${failures["$preset $name"]:-0} + 1))
    done < <(sed -n 's/^[[:space:]]*[0-9]\+ - \([^ ]*\) (.*)$/\1/p' "$log")
  done
  failed_rounds=$((failed_rounds + round_failed))
  echo "=== round $round of $rounds: $((SECONDS - t0)) s, $([[ $round_failed = 0 ]] && echo passed || echo FAILED)"
done

echo "=== failures per test over $rounds rounds:"
if [[ ${#failures[@]} -eq 0 ]]; then
  echo "none"
else
  for key in "${!failures[@]}"; do echo "${failures[$key]} $key"; done | sort -rn
  echo "(the log of each failed round: build/<preset>/repeat-round-<n>.log)"
fi
echo "=== $rounds rounds in $((SECONDS - start)) s (build included)"
[[ $failed_rounds -eq 0 ]]
