#!/usr/bin/env bash
# Fails, naming each file and line, when a C++ source of the project is not as clang-format
# (.clang-format) would write it. Run by the suite as the test `source_format`; fix with
#   clang-format -i FILE...
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(find . -path ./build -prune -o -path './.*' -prune -o \
                       \( -name '*.cpp' -o -name '*.hpp' \) -print | sort)
echo "checking ${#files[@]} sources with $(clang-format --version)"
clang-format --dry-run -Werror "${files[@]}"
