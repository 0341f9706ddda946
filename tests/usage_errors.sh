#!/usr/bin/env bash
# Every program the project builds answers --help with its usage (exit 0) and a usage error with
# an error on stderr and exit status 2, nothing on stdout: the same contract everywhere, so
# scripts can tell a usage error from a failed run. (CLI11 names a missing subcommand or
# required option before an unknown one, so the message need not name the option given.)
# Arguments: the programs' paths.
set -uo pipefail
failed=0
for program in "$@"; do
  name=$(basename "$program")
  ok=1
  help=$("$program" --help 2>&1)
  status=$?
  if [[ $status -ne 0 || $help != *"Usage: "* ]]; then
    echo "FAIL $name --help: exit $status, output: ${help:0:200}"
    ok=0
  fi
  out=$("$program" --no-such-option 2>/tmp/usage_errors.$$)
  status=$?
  err=$(cat /tmp/usage_errors.$$)
  rm -f /tmp/usage_errors.$$
  if [[ $status -ne 2 || -z $err || -n $out ]]; then
    echo "FAIL $name --no-such-option: exit $status (want 2), stderr: ${err:0:200}, stdout: ${out:0:200}"
    ok=0
  fi
  if [[ $ok -eq 1 ]]; then
    echo "ok   $name: --help exits 0; --no-such-option exits 2: ${err%%$'\n'*}"
  else
    failed=1
  fi
done

# Values a program checks, while parsing or right after, refused the same way: the text the
# error must hold, the program's name, then its arguments; exit 2 and nothing on stdout.
bad_value() {
  local want=$1 name=$2 program
  shift 2
  for program in "${programs[@]}"; do [[ $(basename "$program") == "$name" ]] && break; done
  out=$("$program" "$@" 2>/tmp/usage_errors.$$)
  status=$?
  err=$(cat /tmp/usage_errors.$$)
  rm -f /tmp/usage_errors.$$
  if [[ $status -ne 2 || $err != *"$want"* || -n $out ]]; then
    echo "FAIL $name $*: exit $status (want 2 and '$want'), stderr: ${err:0:200}, stdout: ${out:0:200}"
    failed=1
  else
    echo "ok   $name $*: exits 2: ${err%%$'\n'*}"
  fi
}
programs=("$@")
bad_value "'127.0.0.1:99999' is not HOST:PORT" pipeserver --live --viz 127.0.0.1:99999
bad_value "'127.0.0.1:abc' is not HOST:PORT" pipeserver --live --viz 127.0.0.1:abc
bad_value "'127.0.0.1:0' is not HOST:PORT" vizserver --displays 8x4 --servers 1 \
  --display-stream 127.0.0.1:0
# sscanf's %d wrapped 4294967360 to 64; 1e300 s did not fit the milliseconds it became.
bad_value "'4294967360x64' is not WIDTHxHEIGHT" vizserver --displays 4294967360x64 --servers 1 \
  --out /tmp
bad_value "1e300 is not 0 (forever) or 0.001..86400 seconds" vizserver --displays 8x8 \
  --servers 1 --out /tmp --accept-timeout 1e300
# 1e-9 s became 0 ms, which is forever; NaN too.
bad_value "1e-9 is not 0 (forever)" vizserver --displays 8x8 --servers 1 --out /tmp \
  --accept-timeout 1e-9
bad_value "nan is not 0 (forever)" vizserver --displays 8x8 --servers 1 --out /tmp \
  --stall-timeout nan
# Below 1 Hz the run slept through its stall timeout and stop signals; NaN passed CLI::Range.
bad_value "0.05 is not 0 (as fast as possible) or 1..1000 Hz" l2wall run --refresh 0.05 \
  --out /tmp
bad_value "nan is not 0 (as fast as possible) or 1..1000 Hz" l2wall run --refresh nan --out /tmp
bad_value "nan is not 1..1000 Hz" show_wall --rate nan --displays-from /tmp
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
bad_value "WALL excludes --print-default" tilelayout --print-default walls/kd-2x2.toml
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
bad_value "--triangles is an option of --scene strips, not mesh" pipeserver --triangles 10 \
  --out /tmp/x.png
bad_value "--mesh is an option of --scene mesh, not strips" l2wall run --scene strips \
  --mesh /etc/hostname
# NaN passed CLI::Range and made every pixel of the view NaN (a black wall).
bad_value "nan is not a number in 1..170" pipeserver --camera-fov nan --out /tmp/x.png
bad_value "nan is not a number in -360..360" l2wall run --camera-orbit nan
bad_value "--link requires --live" pipeserver --link /l2-x --out /tmp/x.png
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
