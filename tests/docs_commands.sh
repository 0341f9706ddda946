#!/usr/bin/env bash
# The commands the documentation shows are commands the programs take, as written. Every
# command of one of the project's programs in a fenced shell block or the `command` column of
# a table of README.md, the parts' READMEs and docs/*.md (tests/docs_commands.py finds them) is
# run from a scratch folder, its placeholders (WALL, DIR, N, model.glb, /dev/pts/N...) replaced
# by real values there, `l2wall run` at most 3 frames. It must not exit 2 or print a usage
# error ("Run with --help"): what every program does with a command line it does not take. It
# must not crash (end by SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL or SIGTRAP), stopped or not,
# nor leave shared memory behind (its own or a child's /dev/shm/l2-PID-*). A
# usage error comes at once, so a command is stopped, accepted, once it has used 0.1 s of CPU
# time (ten times what a usage error takes) or run $deadline s: it is past its command line.
# A command mpirun starts runs alone, where l2wall stops at once saying mpirun did not start
# it; one under xvfb-run runs with no X display, where it stops once it needs one. A table
# cell that is a fragment (it lacks a required argument) and every command written in the
# text are checked word by word against the program's --help: each option must be one it
# takes, and no more positional arguments than it takes.
# Arguments: the programs' paths.
set -uo pipefail
command -v python3 >/dev/null || { echo "skipped: no python3 to find the commands"; exit 77; }
root=$(cd "$(dirname "$0")/.." && pwd)
helper=$root/tests/docs_commands.py
deadline=${DOCS_COMMANDS_DEADLINE:-2}  # seconds
failed=0
started=${EPOCHREALTIME/./}  # microseconds

# Not run, with why; their words are still checked against --help. Each entry is the start of
# a command as the lines below print it (program name, then its words); one that no longer
# matches a command of the docs fails, so the list follows the docs.
not_run=(
  "l2wall golden update|writes the golden images into the source tree"
  "l2wall run --scene vnc --content desk.example|reaches another machine's VNC server"
)
# Not commands at all: a program's output quoted in the text.
not_commands=(
  "pipeserver 1 disconnected during frame 3|a line the compositing server prints"
)

declare -A path_of
names=()
for program in "$@"; do
  path_of[$(basename "$program")]=$program
  names+=("$(basename "$program")=$program")
done

work=$(mktemp -d)
pty_pid=""
cleanup() {
  [[ -n $pty_pid ]] && kill "$pty_pid" 2>/dev/null && wait "$pty_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work" || exit 1

# What the commands take for granted: the repository's walls, model and example sessions beside
# them (as when run from a working tree), the displays scripts/main.sh writes, a scanned-out
# frame, frames captured from a pipeserver (the test pattern), a picture and a movie, a serial
# line with the emulator's end of the back-channel on it.
ln -s "$root/walls" walls
ln -s "$root/data" data
ln -s "$root/examples" examples
mkdir -p out/default-wall/frame-9
cp "$root"/tests/golden_images/kd-2x2-bunny/display-*.png out/default-wall/frame-9/
"${path_of[tilelayout]}" --scanout out/row-scan >/dev/null
"${path_of[tilelayout]}" --parity 1 --scanout captured >/dev/null
if command -v ffmpeg >/dev/null; then
  ffmpeg -loglevel error -f lavfi -i testsrc=size=320x240:rate=10 -frames:v 1 huge.tif \
    -frames:v 5 -c:v ffv1 clip.mkv
fi
"${path_of[sync_backchannel]}" pty --refresh 10 >pty.txt 2>&1 &
pty_pid=$!
for _ in $(seq 50); do [[ -s pty.txt ]] && break; sleep 0.1; done
pty=$(head -1 pty.txt)
[[ $pty == /dev/pts/* ]] || { echo "FAIL: no pty from sync_backchannel pty: $pty"; exit 1; }

ms() { echo $(((${EPOCHREALTIME/./} - started) / 1000)); }
echo "     $(ms) ms: what the commands take for granted made"
# WHERE KIND MODE WORDS, one command a line (docs_commands.py says what each means).
python3 "$helper" extract "$root" "${names[@]}" >commands.tsv || { echo "FAIL: extract"; exit 1; }
[[ $(wc -l <commands.tsv) -gt 50 ]] || { echo "FAIL: found only $(wc -l <commands.tsv) commands"; exit 1; }

# Runs ARGV in its own process group, output to NAME.out and NAME.err, until it ends, or until
# it is past its command line: it (with its children, as an l2wall run's pipeservers) has
# used $cpu_ticks ticks of CPU time (a usage error takes a tenth of that), or it has been
# running $deadline s. Then it is stopped, the group with SIGTERM (l2wall ends a run on it as
# on Ctrl-C), after 30 s SIGKILL: a run of a wall of many pipeservers takes several seconds
# to end them and remove its shared memory, which SIGKILL would leave behind (a killed run's
# segments are removed here, said in a line). Sets status (its exit status) and stopped (why it was
# stopped, or empty).
cpu_ticks=10
mkfifo pause.fifo
exec {pause}<>pause.fifo  # read -t on it: a pause without starting a process
run_until_accepted() {
  local name=$1 pid ticks polls=0 limit=$((deadline * 20)) child task stat more children
  shift
  seen=()
  setsid env -u DISPLAY -u WAYLAND_DISPLAY -u OMPI_COMM_WORLD_RANK -u OMPI_COMM_WORLD_SIZE \
    "$@" </dev/null >"$name.out" 2>"$name.err" {pause}<&- &
  pid=$!
  pid_run=$pid
  stopped=""
  # Polled with bash's own reads only: a loaded machine is slow to start processes.
  while kill -0 "$pid" 2>/dev/null; do
    children=()
    for task in /proc/"$pid"/task/*/children; do
      read -r -a more <"$task" 2>/dev/null && children+=("${more[@]}")
    done
    ticks=0
    for child in "${children[@]}"; do seen[$child]=1; done
    for child in "$pid" "${children[@]}"; do
      read -r stat <"/proc/$child/stat" 2>/dev/null || continue
      read -r -a stat <<<"${stat##*) }"  # after the ")" that ends the name: state, ppid, ...
      [[ ${stat[0]} == Z ]] && continue
      ticks=$((ticks + stat[11] + stat[12]))  # utime, stime (fields 14 and 15)
    done
    if ((ticks >= cpu_ticks)); then
      stopped="after $((ticks * 10)) ms of CPU time"
    elif ((++polls > limit)); then
      stopped="still running after $deadline s"
    fi
    [[ -n $stopped ]] && break
    read -r -t 0.05 -u "$pause" _
  done
  if [[ -n $stopped ]]; then
    kill -TERM -- -"$pid" 2>/dev/null
    for ((polls = 0; polls < 600; polls++)); do
      kill -0 "$pid" 2>/dev/null || break
      read -r -t 0.05 -u "$pause" _
    done
    if kill -KILL -- -"$pid" 2>/dev/null; then
      left_by "$pid"
      ((${#left[@]} == 0)) || { rm -f "${left[@]}" &&
        echo "     (killed 30 s after SIGTERM: removed ${#left[@]} shared-memory segments it left)"; }
    fi
  fi
  wait "$pid"
  status=$?
  kill -KILL -- -"$pid" 2>/dev/null  # what the group left behind
}

# left_by PID: sets `left` to the shared-memory segments (DVI links, named by the process that
# made them: /dev/shm/l2-PID-*) of PID and of the children seen while it ran (an `l2wall golden`
# runs `l2wall run` as a child).
left_by() {
  local p segment
  left=()
  for p in "$1" "${!seen[@]}"; do
    for segment in /dev/shm/l2-"$p"-*; do [[ -e $segment ]] && left+=("$segment"); done
  done
}

# listed ENTRIES... -- TEXT: whether TEXT starts as an entry of a list above does; `why` is
# then the entry's reason. (No subshells here or below: a loaded machine is slow to start them.)
declare -A used seen
listed() {
  local text=${*: -1} entry
  for entry in "${@:1:$#-2}"; do
    if [[ $text == "${entry%%|*}"* ]]; then
      why=${entry#*|}
      used[${entry%%|*}]=1
      return 0
    fi
  done
  return 1
}

: >words.tsv
runs=0
while IFS=$'\t' read -r where kind mode words; do
  words=${words//\{pty\}/$pty}
  eval "argv=($words)"  # shell-quoted by the helper: words only, nothing expanded
  expanded=()
  for word in "${argv[@]}"; do  # a pattern, as the shell would expand it here
    if [[ $word == *[*?]* ]] && matches=$(compgen -G "$word"); then
      mapfile -t -O "${#expanded[@]}" expanded <<<"$matches"
    else
      expanded+=("$word")
    fi
  done
  argv=("${expanded[@]}")
  text="${argv[0]##*/}${argv[1]+ ${argv[*]:1}}"  # "name words...", as the lists and lines say
  if listed "${not_commands[@]}" -- "$text"; then
    echo "skip $where: $text: $why"
    continue
  fi
  if [[ $mode == words ]]; then
    printf '%s\t%s\n' "$where" "$words" >>words.tsv
    continue
  fi
  if listed "${not_run[@]}" -- "$text"; then
    echo "skip $where: $text: not run: $why"
    printf '%s\t%s\n' "$where" "$words" >>words.tsv
    continue
  fi
  if [[ $text == *huge.tif* || $text == *clip.mkv* ]] && [[ ! -e huge.tif ]]; then
    echo "skip $where: $text: not run: no ffmpeg here to make the picture and the movie"
    printf '%s\t%s\n' "$where" "$words" >>words.tsv
    continue
  fi
  if [[ $mode == help ]]; then  # PROGRAM SUB: SUB among the subcommands its --help lists
    subcommands=$("${argv[0]}" --help 2>&1 |
      awk '/^Subcommands:/ {on = 1; next} on && /^$/ {on = 0} on && /^  [a-z]/ {print $1}')
    if grep -qxF -- "${argv[1]}" <<<"$subcommands"; then
      echo "ok   $where: $text: a subcommand (--help lists it)"
    else
      echo "FAIL $where: $text: not a subcommand; --help lists: ${subcommands//$'\n'/ }"
      failed=1
    fi
    continue
  fi
  # run or mpi: from the scratch folder, without an X display or mpirun's environment.
  runs=$((runs + 1))
  begun=${EPOCHREALTIME/./}
  run_until_accepted "run-$runs" "${argv[@]}"
  took="$(((${EPOCHREALTIME/./} - begun) / 1000)) ms"
  err=$(head -c 300 "run-$runs.err")
  left_by "$pid_run"
  if ((${#left[@]} > 0)); then
    echo "FAIL $where: $text: left shared memory behind (${left[*]})${stopped:+; it was stopped $stopped}"
    rm -f "${left[@]}"
    failed=1
  fi
  if ((status > 128)) && [[ " 132 133 134 135 136 139 " == *" $status "* ]]; then
    echo "FAIL $where: $text: crashed (exit $status: signal $((status - 128)))${stopped:+, stopped $stopped}: ${err%%$'\n'*}"
    failed=1
  elif [[ $status -eq 2 || $err == *"Run with --help"* ]]; then
    if [[ $kind == table && $err == *required* ]]; then
      echo "part $where: $text: a fragment (${err%%$'\n'*}): its words checked below"
      printf '%s\t%s\n' "$where" "$words" >>words.tsv
      continue
    fi
    echo "FAIL $where: $text: exit $status, a usage error: ${err%%$'\n'*}"
    failed=1
  elif [[ $mode == mpi && $err != *"not started by mpirun"* ]]; then
    echo "FAIL $where: $text: run without mpirun, exit $status without saying so: ${err:0:200}"
    failed=1
  elif [[ -n $stopped ]]; then
    echo "ok   $where: $text: accepted, stopped $stopped ($took)"
  else
    echo "ok   $where: $text: exit $status ($took)${err:+: ${err%%$'\n'*}}"
  fi
done <commands.tsv

echo "     $(ms) ms: $runs commands run"
python3 "$helper" check-words "${names[@]}" <words.tsv || failed=1

for entry in "${not_run[@]}" "${not_commands[@]}"; do
  [[ -n ${used[${entry%%|*}]:-} ]] ||
    { echo "FAIL: skip entry '${entry%%|*}' matches no command of the docs: remove it"; failed=1; }
done
echo "$(wc -l <commands.tsv) commands, $runs run, in $(ms) ms"
exit $failed
