#!/usr/bin/env bash
# README command 2, and what CI runs: installs what is missing, then builds and runs the suite
# three times — release (every test), ASan+UBSan (tests labelled asan) and TSan (tests labelled
# tsan: the threaded ones). The sanitizer runs build only the executables their tests need. Then
# a fuzz smoke run: the libFuzzer harnesses (fuzz/) for a few seconds each, failing on any crash.
#
# Each build after the first runs while the tests before it run, at the idle scheduling
# priority (SCHED_IDLE): the tests wait on processes, timeouts and refresh clocks much of the
# time, and the compiler takes only the CPU time they leave, so the tests run as they would
# alone. A build's output goes to build/<preset>/suite-build.log and is shown if it fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

jobs=$(nproc)
start=$SECONDS

build() {  # build PRESET [TARGET]; without TARGET, what the build preset builds
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1" -j "$jobs" ${2:+--target "$2"} -- --quiet
}
# Builds at idle priority in the background (background_build); `finish_build` waits for them.
# SCHED_IDLE where the system lets us set it, else the lowest nice level.
idle=(chrt --idle 0)
"${idle[@]}" true 2>/dev/null || idle=(nice -n 19)
background_pid=
background_presets=()
# background_build PRESET[:TARGET]...: the builds one after another, in one background job.
background_build() {
  local spec preset target chain=""
  background_presets=()
  for spec in "$@"; do
    preset=${spec%%:*}
    mkdir -p "build/$preset"
    rm -f "build/$preset/suite-build.log"
    background_presets+=("$preset")
    [[ $spec == *:* ]] && target=${spec#*:} || target=""
    echo "=== $preset: build (${target:-the targets of its build preset}), beside the tests"
    chain+="build $preset $target >build/$preset/suite-build.log 2>&1; "
  done
  setsid "${idle[@]}" bash -c "set -euo pipefail; $(declare -f build); jobs=$jobs; $chain" &
  background_pid=$!
}
# A failing test ends the suite: the build beside it (its own process group) goes with it.
trap '[[ -z $background_pid ]] || kill -- -"$background_pid" 2>/dev/null || true' EXIT
finish_build() {
  local t0=$SECONDS preset
  if ! wait "$background_pid"; then
    for preset in "${background_presets[@]}"; do
      [[ ! -f build/$preset/suite-build.log ]] || cat "build/$preset/suite-build.log"
    done
    echo "=== ${background_presets[*]}: build failed"
    exit 1
  fi
  background_pid=
  echo "=== ${background_presets[*]}: build finished ($((SECONDS - t0)) s waited for it)"
}
run_tests() {  # run_tests PRESET
  local t0=$SECONDS
  echo "=== $1: test"
  ctest --preset "$1" -j "$jobs"
  echo "=== $1: tests took $((SECONDS - t0)) s"
}

t0=$SECONDS
echo "=== default: build (all)"
build default
echo "=== default: build took $((SECONDS - t0)) s"
background_build asan:l2_asan_tests
run_tests default
finish_build
# The TSan and fuzz builds together beside the ASan tests: the fuzz build waited alone after
# the short TSan tests.
background_build tsan:l2_tsan_tests fuzz
run_tests asan
finish_build
run_tests tsan
t0=$SECONDS
echo "=== fuzz: smoke run"
bash scripts/fuzz.sh 3
echo "=== fuzz: $((SECONDS - t0)) s"
echo "=== suite finished in $((SECONDS - start)) s"
