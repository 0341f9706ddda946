#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, CMake preset "fuzz": clang, ASan+UBSan) and runs each
# for SECONDS seconds from its seed corpus (fuzz/corpus/<harness>), then prints per harness the
# executions, their rate, and libFuzzer's coverage figures (cov: code edges, ft: features) from
# its last status line. Exits 1 if any harness crashed, hung (over 10 s on one input) or
# broke a promise; the input that did it is saved in build/<preset>/runs/<harness>/artifacts/
# (under FUZZ_OUT instead of build/<preset>/runs when set).
# Usage: scripts/fuzz.sh SECONDS [HARNESS...]   (default: all of them)
# FUZZ_RUNS=N also stops each harness after N executions (a long run: FUZZ_RUNS=10000000 with
# SECONDS as the upper bound). FUZZ_JOBS=N runs N harnesses at a time (default: one a core).
# FUZZ_PRESET=fuzz-long builds them with LeakSanitizer's allocator alone (build/fuzz-long): several
# times the executions a second where a harness's time goes to libraries ASan does not
# instrument (the picture readers), its allocation limit and leak check kept.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ || $1 -lt 1 ]]; then
  echo "usage: scripts/fuzz.sh SECONDS [HARNESS...]  (SECONDS per harness, 1 or more)" >&2
  exit 2
fi
seconds=$1
shift
harnesses=("$@")
((${#harnesses[@]})) || harnesses=(scanline ready wall_file session_file colour_lut warp_pfm wall_import mpcdi_import vizserver_wire png_frame picture_header jpeg_frame picture_file frame_delta control_line tuio)

preset=${FUZZ_PRESET:-fuzz}
[[ $preset == fuzz || $preset == fuzz-long ]] ||
  { echo "fuzz.sh: FUZZ_PRESET '$preset' is not fuzz or fuzz-long" >&2; exit 2; }
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" -- --quiet

out=${FUZZ_OUT:-build/$preset/runs}  # FUZZ_OUT: another folder, for a run beside this one
# FUZZ_JOBS harnesses run side by side (default: one a core): each is one process, so the smoke
# run takes SECONDS per FUZZ_JOBS harnesses. Their lines are printed in the list's order.
jobs=${FUZZ_JOBS:-$(nproc)}

# fuzz_one HARNESS: runs it, writes its summary line to $out/HARNESS/summary.txt, exits 1 when
# it crashed, hung or broke a promise.
fuzz_one() {
  local h=$1 seeds=fuzz/corpus/$1
  # Inputs found worth keeping go to a scratch corpus, never into the committed seeds.
  local work=$out/$h/corpus artifacts=$out/$h/artifacts/ log=$out/$h/log.txt
  mkdir -p "$work" "$artifacts"
  # A READY message is 17 bytes: 512 hold thirty, and longer inputs only slow the search.
  local limits=()
  [[ $h == ready ]] && limits=(-max_len=512)
  # Wall and session files as large as the 100 KB one whose nesting overflowed toml++'s stack:
  # the shape check that refuses it must itself hold at that size.
  [[ $h == wall_file || $h == session_file ]] && limits=(-max_len=131072)
  # Wall configurations are a few kilobytes; the example nDisplay file is under 8 KB.
  [[ $h == wall_import ]] && limits=(-max_len=16384)
  # An mpcdi.xml of a few projectors is 2 to 4 KB; 16 KB hold dozens of regions.
  [[ $h == mpcdi_import ]] && limits=(-max_len=16384)
  # A warp of the largest display the harness picks (16x16 points) is 3 KB with its header.
  [[ $h == warp_pfm ]] && limits=(-max_len=4096)
  # Pictures: no one allocation past what the checks let a reader take (a picture decoded whole,
  # 512 MiB, with room), nor the process past 2 GB; files of up to 64 kB.
  [[ $h == picture_file ]] && limits=(-max_len=65536 -malloc_limit_mb=1024 -rss_limit_mb=2048)
  local status=0
  build/"$preset"/fuzz/fuzz_"$h" "$work" "$seeds" "${limits[@]}" -max_total_time="$seconds" -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$artifacts" ${FUZZ_RUNS:+-runs="$FUZZ_RUNS"} \
    >"$log" 2>&1 || status=$?
  # A harness ended mid-input (a crash, a timeout) leaves its input's file; fuzz_picture_file's
  # is named after its process, which has ended.
  [[ $h != picture_file ]] || rm -f /dev/shm/l2-fuzz-picture-[0-9]* /tmp/l2-fuzz-picture-[0-9]*
  local runs rate last cov ft corpus verdict took
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corpus=$(sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<<"$last")
  if ((status == 0)); then
    verdict="no crash"
  else
    verdict="FAILED (exit $status, see $log)"
    # The sanitizers' and libFuzzer's own lines ("==PID==ERROR", "==PID== ERROR", "SUMMARY",
    # "LeakSanitizer has encountered a fatal error"), else the log's last lines: a CI log holds
    # only what the script prints, not the harness's log.
    grep -E '^(==[0-9]+== ?ERROR|==[0-9]+==.*Sanitizer|fuzz: broken promise|SUMMARY)' "$log" |
      head -4 >"$out/$h/why.txt" || true
    [[ -s $out/$h/why.txt ]] || tail -n 6 "$log" >"$out/$h/why.txt"
  fi
  took=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  printf 'fuzz_%-15s %12s runs in %s s (%s/s)  cov %s  ft %s  corpus %s  %s\n' "$h" \
    "${runs:-?}" "${took:-$seconds}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corpus:-?}" \
    "$verdict" >"$out/$h/summary.txt"
  ((status == 0))
}

for h in "${harnesses[@]}"; do
  [[ -d fuzz/corpus/$h ]] || { echo "fuzz: no harness '$h' (no fuzz/corpus/$h)" >&2; exit 2; }
  rm -f "$out/$h/summary.txt" "$out/$h/why.txt"
done
pids=()
for h in "${harnesses[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  fuzz_one "$h" &
  pids+=($!)
done
failed=0
for i in "${!harnesses[@]}"; do
  h=${harnesses[$i]}
  wait "${pids[$i]}" || failed=1
  cat "$out/$h/summary.txt"
  [[ ! -s $out/$h/why.txt ]] || sed 's/^/    /' "$out/$h/why.txt"
done
exit $failed
