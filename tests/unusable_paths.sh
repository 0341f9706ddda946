#!/usr/bin/env bash
# Output paths and input frames a program cannot use are refused with one line in the project's
# words, naming the path and the reason, and the program's status for unusable files;
# std::filesystem's own text ("filesystem error: cannot create directories: Not a directory
# [x/y]") reached users. A regular file stands where a folder is expected: the tests run as
# root, where permissions do not stop.
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
  --pipeservers 1 --out "$tmp/file/out"
refused 1 "pipeserver: --out $tmp/file/out: $in_the_way" pipeserver --out "$tmp/file/out"
refused 1 "pipeserver: --out $tmp/file: a file, not a folder" pipeserver --out "$tmp/file"
# Refused before rendering: the scanned-out frame is not written either.
refused 1 "pipeserver: --reference $tmp/file: a file, not a folder" pipeserver \
  --out "$tmp/frames" --reference "$tmp/file"
if [[ -e $tmp/frames/scanout-0.png ]]; then
  echo "FAIL pipeserver wrote $tmp/frames/scanout-0.png before refusing --reference"
  failed=1
fi

# A frame that cannot be used is an unusable file, exit 1 (strip_headers said 2, a usage error).
# A 2x1 grey PNG: it cannot hold strip headers.
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x02\x00\x00\x00\x01\x08\x00\x00\x00\x00\xd1I V\x00\x00\x00\x0bIDATx\x9cc`?\x01\x00\x00\xd9\x00\xd0\xd7\xa6"<\x00\x00\x00\x00IEND\xaeB`\x82' \
  >"$tmp/grey.png"
refused 1 "strip_headers: $tmp/grey.png: a grayscale picture (one colour channel) cannot hold \
strip headers: a header is 48 bits in the R, G and B bytes of two pixels" strip_headers dump \
  "$tmp/grey.png"
head -c 40 "$tmp/grey.png" >"$tmp/truncated.png"
refused 1 "strip_headers: $tmp/truncated.png: cannot read: the PNG file ends early (truncated)" \
  strip_headers dump "$tmp/truncated.png"
exit $failed
