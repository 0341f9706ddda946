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
exit $failed
