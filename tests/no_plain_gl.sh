#!/usr/bin/env bash
# No plain gl* symbol, and no OSMesa function, is imported by the files given (programs and
# static libraries): every GL call goes through a context's function table (gl_api.hpp), and
# libOSMesa is loaded by name. A plain call would reach one library's contexts only, in a process
# that holds OSMesa and EGL (or a window's libGL) together: it would draw into no context under
# the other renderer, without a word.
set -uo pipefail
failed=0
for file in "$@"; do
  if [[ $file == *.a ]]; then
    imports=$(nm --undefined-only "$file" 2>/dev/null | awk '$1 == "U" {print $2}')
  else
    imports=$(nm -D --undefined-only "$file" | awk '$1 == "U" {print $2}')
  fi
  plain=$(grep -E '^(gl[A-Z]|OSMesa)' <<<"$imports" | sort -u | paste -sd' ' -)
  if [[ -n $plain ]]; then
    echo "FAIL $file imports $plain"
    failed=1
  else
    echo "ok   $file: $(grep -c . <<<"$imports") imports, no gl* or OSMesa*"
  fi
done
exit $failed
