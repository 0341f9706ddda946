#!/usr/bin/env bash
# Output paths a program cannot use are refused with one line in the project's words, naming the
# path and the reason, and the program's status for unusable files; std::filesystem's own text
# ("filesystem error: cannot create directories: Not a directory [x/y]") reached users. A regular
# file stands where a folder is expected: the tests run as root, where permissions do not stop.
# Arguments: the programs' paths.
set -uo pipefail
failed=0
programs=("$@")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
touch "$tmp/file"

# The status wanted, the whole of stderr wanted, the program's name, then its arguments.
refused() {
  local want_status=$1 want=$2 name=$3 program
  shift 3
  for program in "${programs[@]}"; do [[ $(basename "$program") == "$name" ]] && break; done
  "$program" "$@" >/dev/null 2>"$tmp/stderr"
  local status=$?
  local err
  err=$(cat "$tmp/stderr")
  if [[ $status -ne $want_status || $err != "$want" ]]; then
    echo "FAIL $name $*: exit $status (want $want_status), stderr:"
    echo "$err"
    echo "wanted:"
    echo "$want"
    failed=1
  else
    echo "ok   $name $*: exits $status: $err"
  fi
}

in_the_way="cannot make the folder: $tmp/file is a file, not a folder"
refused 1 "lightning2_emu: --out $tmp/file/out: $in_the_way" lightning2_emu route \
  --displays 8x8 --out "$tmp/file/out" "$tmp/in.png"
refused 1 "lightning2_emu: --out $tmp/file: a file, not a folder" lightning2_emu route \
  --displays 8x8 --out "$tmp/file" "$tmp/in.png"
refused 1 "lightning2_emu: --out $tmp/file/out: $in_the_way" lightning2_emu sequence \
  --displays 8x8 --out "$tmp/file/out" "$tmp"
refused 3 "tilelayout: --png $tmp/file/out: $in_the_way" tilelayout --png "$tmp/file/out"
refused 3 "tilelayout: --scanout $tmp/file: a file, not a folder" tilelayout \
  --scanout "$tmp/file"
refused 1 "l2wall: --out $tmp/file/out: $in_the_way" l2wall run --frames 1 --out "$tmp/file/out"
refused 1 "vizserver: error: --out $tmp/file/out: $in_the_way" vizserver --displays 8x8 \
  --servers 1 --out "$tmp/file/out"
refused 1 "pipeserver: $tmp/file/out: $in_the_way" pipeserver --out "$tmp/file/out/frame.png"
# Refused before rendering: the scanned-out frame is not written either.
refused 1 "pipeserver: --reference $tmp/file: a file, not a folder" pipeserver \
  --out "$tmp/frame.png" --reference "$tmp/file"
if [[ -e $tmp/frame.png ]]; then
  echo "FAIL pipeserver wrote $tmp/frame.png before refusing --reference"
  failed=1
fi
exit $failed
