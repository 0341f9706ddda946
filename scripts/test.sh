#!/usr/bin/env bash
# README command 2, and what CI runs: installs what is missing, then builds and runs the suite
# three times — release (every test), ASan+UBSan (tests labelled asan) and TSan (tests labelled
# tsan: the threaded ones). The sanitizer runs build only the executables their tests need. Then
# a fuzz smoke run: the libFuzzer harnesses (fuzz/) for a few seconds each, failing on any crash.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

jobs=$(nproc)
start=$SECONDS
run_preset() {
  local preset=$1 target=${2:-all}
  local t0=$SECONDS
  echo "=== $preset: build ($target)"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs" --target "$target" -- --quiet
  echo "=== $preset: test"
  ctest --preset "$preset" -j "$jobs"
  echo "=== $preset: $((SECONDS - t0)) s"
}
run_preset default
run_preset asan l2_asan_tests
run_preset tsan l2_tsan_tests
t0=$SECONDS
echo "=== fuzz: build and smoke run"
bash scripts/fuzz.sh 3
echo "=== fuzz: $((SECONDS - t0)) s"
echo "=== suite finished in $((SECONDS - start)) s"
