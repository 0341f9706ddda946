#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds the release and sanitizer presets and
# runs every CTest suite. This is README command 2 and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

start=$SECONDS
for preset in default asan tsan; do
  echo "=== build: $preset"
  bash scripts/build.sh "$preset"
  echo "=== test: $preset"
  ctest --preset "$preset" -j "$(nproc)"
done
echo "=== suite finished in $((SECONDS - start)) s"
