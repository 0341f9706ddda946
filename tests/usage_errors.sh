#!/usr/bin/env bash
# One command-line language across the project's programs. Every program and subcommand answers
# --help with its usage (exit 0) and a usage error with one error on stderr that starts with the
# program's name, exit status 2, nothing on stdout: the same contract everywhere, so scripts can
# tell a usage error from a failed run. (CLI11 names a missing subcommand or required option
# before an unknown one, so the message need not name the option given.) The same option is
# spelled, typed and defaulted the same way in every --help (command_line/options.hpp).
# Arguments: the programs' paths.
set -uo pipefail
failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
root=$(cd "$(dirname "$0")/.." && pwd)
helps=$tmp/helps

# --help and an unknown option of `program words...`, then of each of its subcommands; every
# help line goes to $helps as "program words: line".
check_command() {
  local program=$1 name label help status out err sub
  shift
  name=$(basename "$program")
  label="$name${*:+ $*}"
  help=$("$program" "$@" --help 2>&1)
  status=$?
  if [[ $status -ne 0 || $help != *"Usage: "* ]]; then
    echo "FAIL $label --help: exit $status, output: ${help:0:200}"
    failed=1
  fi
  sed "s|^|$label: |" <<<"$help" >>"$helps"
  out=$("$program" "$@" --no-such-option 2>"$tmp/stderr")
  status=$?
  err=$(cat "$tmp/stderr")
  if [[ $status -ne 2 || $err != "$name: "* || -n $out ]]; then
    echo "FAIL $label --no-such-option: exit $status (want 2), stderr (want '$name: ...'):" \
      "${err:0:200}, stdout: ${out:0:200}"
    failed=1
  else
    echo "ok   $label: --help exits 0; --no-such-option exits 2: ${err%%$'\n'*}"
  fi
  for sub in $(awk '/^Subcommands:/ {on = 1; next} on && /^$/ {on = 0} on && /^  [a-z]/ {print $1}' \
    <<<"$help"); do
    check_command "$program" "$@" "$sub"
  done
}
for program in "$@"; do check_command "$program"; done

# The options of every help: "command|option|what follows the option on its line".
awk '{
  label = $0; sub(/: .*/, "", label); line = substr($0, length(label) + 3)
  if (match(line, /^  (  )?(-[a-zA-Z],)?--[a-z0-9-]+/)) {  # 4 spaces: an option group'"'"'s
    name = substr(line, RSTART, RLENGTH); sub(/^ +(-[a-zA-Z],)?/, "", name)
    print label "|" name "|" substr(line, RSTART + RLENGTH)
  }
}' "$helps" >"$tmp/options"
spelling() {
  echo "FAIL $1: $2"
  failed=1
}
while IFS='|' read -r label name rest; do
  case $name in
    --rate | --interval) spelling "$label" "$name: a rate is --refresh HZ everywhere" ;;
    --server | --servers) spelling "$label" "$name: a pipeserver is --pipeserver, their count --pipeservers" ;;
    --host | --port) spelling "$label" "$name: the compositing server's address is --viz-host/--viz-port" ;;
    --timeout | --retries) spelling "$label" "$name: READY waits are --ready-timeout/--ready-retries" ;;
    --refresh) [[ $rest == " HZ:"* ]] || spelling "$label" "--refresh$rest: not in HZ" ;;
    --out) [[ $rest == " DIR"* ]] ||
      spelling "$label" "--out$rest: not a folder (DIR)" ;;
    --wall) [[ $rest == " FILE"* ]] || spelling "$label" "--wall$rest: not a FILE" ;;
    --*-timeout | --duration) [[ $rest == " MS:"* ]] || spelling "$label" "$name$rest: not in MS" ;;
    --threads) [[ $rest == " N:INT in [0 - 64]=1"* ]] ||
      spelling "$label" "--threads$rest: not 0..64 with the default 1" ;;
    --renderer) [[ $rest == " TEXT:egl|osmesa|auto=auto"* ]] ||
      spelling "$label" "--renderer$rest: not egl|osmesa|auto with the default auto" ;;
  esac
done <"$tmp/options"
# The wall is --wall FILE, never a positional argument.
if grep -E '^[^:]+:  (wall|walls|WALL)( |$)' "$helps"; then
  spelling "positional" "a wall given as a positional argument, not --wall"
fi
for option in --wall --refresh --out --threads --stall-timeout --ready-timeout --renderer; do
  users=$(awk -F'|' -v o="$option" '$2 == o {print $1}' "$tmp/options" | sort -u | paste -sd, -)
  echo "     $option is in: ${users:-(none)}"
done

# Values a program checks, while parsing or right after, refused the same way: the text the
# error must hold, the program's name, then its arguments; exit 2 and nothing on stdout.
bad_value() {
  local want=$1 name=$2 program
  shift 2
  for program in "${programs[@]}"; do [[ $(basename "$program") == "$name" ]] && break; done
  out=$("$program" "$@" 2>"$tmp/stderr")
  status=$?
  err=$(cat "$tmp/stderr")
  if [[ $status -ne 2 || $err != "$name: "* || $err != *"$want"* || -n $out ]]; then
    echo "FAIL $name $*: exit $status (want 2 and '$want'), stderr: ${err:0:200}, stdout: ${out:0:200}"
    failed=1
  else
    echo "ok   $name $*: exits 2: ${err%%$'\n'*}"
  fi
}
programs=("$@")
bad_value "'127.0.0.1:99999' is not HOST:PORT" pipeserver --live --viz 127.0.0.1:99999
bad_value "'127.0.0.1:abc' is not HOST:PORT" pipeserver --live --viz 127.0.0.1:abc
bad_value "'127.0.0.1:0' is not HOST:PORT" vizserver --displays 8x4 --pipeservers 1 \
  --display-stream 127.0.0.1:0
# sscanf's %d wrapped 4294967360 to 64; 1e300 s did not fit the milliseconds it became.
bad_value "'4294967360x64' is not WIDTHxHEIGHT" vizserver --displays 4294967360x64 \
  --pipeservers 1 --out /tmp
# Timeouts are whole milliseconds: a fraction, an exponent or NaN is refused, not rounded to 0
# (forever) or clamped.
bad_value "1e300 is not 0 (forever) or 1..86400000 ms" vizserver --displays 8x8 \
  --pipeservers 1 --out /tmp --accept-timeout 1e300
bad_value "0.5 is not 0 (forever) or 1..86400000 ms" vizserver --displays 8x8 --pipeservers 1 \
  --out /tmp --accept-timeout 0.5
bad_value "nan is not 0 (forever) or 1..86400000 ms" vizserver --displays 8x8 --pipeservers 1 \
  --out /tmp --stall-timeout nan
bad_value "0 is not 1..86400000 ms" l2wall run --stall-timeout 0 --out /tmp
bad_value "86400001 is not 1..86400000 ms" sync_backchannel wait-ready /dev/null --frame 1 \
  --ready-timeout 86400001
# Below 1 Hz the run slept through its stall timeout and stop signals; NaN passed CLI::Range.
bad_value "0.05 is not 0 (as fast as possible) or 1..1000 Hz" l2wall run --refresh 0.05 \
  --out /tmp
bad_value "nan is not 0 (as fast as possible) or 1..1000 Hz" l2wall run --refresh nan --out /tmp
bad_value "nan is not 1..1000 Hz" show_wall --refresh nan --displays-from /tmp
bad_value "0.5 is not 1..1000 Hz" sync_backchannel pty --refresh 0.5
# A kept frame past the last one kept nothing, without a word.
bad_value "--keep: frame 7 is past the last frame" l2wall run --frames 3 --keep 7 --out /tmp
bad_value "--compare needs --path both" l2wall run --compare --out /tmp
bad_value "--mpi: --path vizserver does not run over MPI alone" l2wall run --mpi --path vizserver \
  --out /tmp
bad_value "--inject-noise: frame 99 is past the last frame" l2wall run --frames 3 \
  --inject-noise 99 --out /tmp
# --start near LLONG_MAX overflowed start + lines sent (signed: undefined).
bad_value "--start: Value 9223372036854775000 not in range" sync_backchannel pty \
  --start 9223372036854775000
# CLI11 clamped 2^64 to 2^63-1 and sent READY 775807.
bad_value "18446744073709551616 is not a frame number" sync_backchannel send-ready /dev/null \
  --frame 18446744073709551616
# 5000 threads hung the emulator when the system would not start them all.
bad_value "--threads: Value 5000 not in range" lightning2_emu route --displays 8x8 --out /tmp \
  --threads 5000 x.png
# tilelayout ignored these without a word.
bad_value "--parity requires --scanout" tilelayout --parity 1
bad_value "--wall excludes --print-default" tilelayout --print-default \
  --wall "$root/walls/kd-2x2.toml"
# The wall is an option: a file name alone is an argument no program takes.
bad_value "The following argument was not expected: $root/walls/kd-2x2.toml" tilelayout \
  "$root/walls/kd-2x2.toml"
bad_value "--wall: File does not exist: /nonexistent.toml" l2wall run --wall /nonexistent.toml
# A mistyped option was only "not expected": the closest option of that (sub)command is named.
bad_value "not expected: 60 --refrsh (did you mean --refresh?)" l2wall run --refrsh 60
bad_value "not expected: x --wal (did you mean --wall?)" tilelayout --wal x
bad_value "not expected: --ready-timout=5 (did you mean --ready-timeout?)" pipeserver \
  --ready-timout=5 --out /tmp/x
# lightning2_emu: what its options say in their text is a usage error too (it exited 1).
bad_value "--displays: display 0: '640x' is not WIDTHxHEIGHT" lightning2_emu route \
  --displays 640x --out /tmp x.png
bad_value "give either --displays" lightning2_emu route --out /tmp x.png
bad_value "--groups: display 1: group -1 is not 0..63" lightning2_emu route --displays 8x8,8x8 \
  --groups 0,-1 --out /tmp x.png
bad_value "--mesh/--board-max/--displays: board input limit must be 2x1..4096x4096, got \
5000x5000" lightning2_emu route --displays 8x8 --board-max 5000x5000 --out /tmp x.png
bad_value "--mesh/--board-max/--displays: mesh columns must be 1..8" lightning2_emu route \
  --displays 8x8 --mesh 1x9 --out /tmp x.png
bad_value "--ticks: Value 1000000 not in range" lightning2_emu sequence --displays 8x8 \
  --ticks 1000000 --out /tmp /tmp
# An empty --out wrote into the current folder without a word (l2wall: "Invalid argument []").
bad_value "--out: an empty path" lightning2_emu route --displays 8x8 --out '' x.png
bad_value "--out: an empty path" l2wall run --out ''
# Options of a mode or scene not asked for were ignored without a word.
bad_value "--triangles is an option of --scene strips or hotspot, not mesh" pipeserver --triangles 10 \
  --out /tmp/x
bad_value "--mesh is an option of --scene mesh, not strips" l2wall run --scene strips \
  --mesh /etc/hostname
bad_value "--content is an option of --scene picture, movie or vnc, not swap" pipeserver \
  --scene swap --content /etc/hostname --out /tmp/x.png
bad_value "--scene movie needs --content FILE" l2wall run --scene movie
bad_value "--picture-cache-mb is an option of --scene picture or session, not swap" l2wall run \
  --scene swap --picture-cache-mb 16
bad_value "expected X,Y, two numbers (picture pixels), got 10" l2wall run --scene picture \
  --content /etc/hostname --pan 10
bad_value "--zoom is an option of --scene picture, not mesh" pipeserver --zoom 2 --out /tmp/x
bad_value "0 is not a number in 1..100000" pipeserver --scene picture --content /etc/hostname \
  --picture-cache-mb 0 --out /tmp/x
# NaN passed CLI::Range and made every pixel of the view NaN (a black wall).
bad_value "nan is not a number in 1..170" pipeserver --camera-fov nan --out /tmp/x
bad_value "nan is not a number in -360..360" l2wall run --camera-orbit nan
bad_value "--link requires --live" pipeserver --link /l2-x --out /tmp/x
# --renderer means one thing everywhere: l2wall run checks it as every pipeserver does.
bad_value "--renderer: expected egl, osmesa or auto, got bogus" pipeserver --renderer bogus \
  --out /tmp/x
bad_value "--renderer: expected egl, osmesa or auto, got bogus" l2wall run --renderer bogus
bad_value "--renderer: expected egl, osmesa or auto, got EGL" spinning_cubes --renderer EGL \
  --out /tmp/x
bad_value "--viz-host and --viz-port need --path vizserver or both" l2wall run --viz-port 5000 \
  --out /tmp
# EXT headers: fields used to be narrowed to their types (display 300 became 44, x 65541 5).
bad_value "field 'display' = 300 is outside 0..63" strip_headers encode --op ext --display 300
bad_value "field 'x' = 65541 is outside 0..4095" strip_headers encode --op ext --x 65541
# END has no fields and SKIP only a width: they were dropped without a word.
bad_value "--op end: END has no fields" strip_headers encode --op end --display 3 --width 30
bad_value "--op skip: SKIP has only a --width" strip_headers encode --op skip --x 5 --width 30
# Hex digits only (stoull took -1 as ffffffffffffffff, and a 0x prefix), below 2^48.
for value in -1 +1 0x1 ' 1' 1000000000000 ''; do
  bad_value "'$value' is not a 48-bit hex value" strip_headers decode -- "$value"
done
# A header is exactly 12 hex digits: one left out (11) was read as a leading zero and decoded as
# another header, a check error (exit 1); a 13th digit, a leading zero, was taken too.
bad_value "'4180500a00f' is not a 48-bit hex value (12 hex digits, not 11)" strip_headers decode \
  4180500a00f
bad_value "'0629400f00a01' is not a 48-bit hex value (12 hex digits, not 13)" strip_headers \
  decode 0629400f00a01
# The extension word (§7): a KEY needs its colour, a DEPTH has none; kinds and colours exactly.
bad_value "--kind key needs --key RRGGBB" strip_headers ext --kind key
bad_value "--kind depth: DEPTH carries no key" strip_headers ext --kind depth --key 000001
bad_value "'kex' is not key, depth or a kind number 0..15" strip_headers ext --kind kex
bad_value "'16' is not key, depth or a kind number 0..15" strip_headers ext --kind 16
bad_value "'0xff00' is not a colour RRGGBB (6 hex digits)" strip_headers ext --kind key \
  --key 0xff00
bad_value "'1000ff00001' is not a 48-bit hex value (12 hex digits, not 11)" strip_headers decode \
  --ext 1000ff00001
exit $failed
