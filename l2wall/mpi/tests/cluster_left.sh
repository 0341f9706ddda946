# What a run on the namespace cluster (scripts/cluster.sh) must leave behind: nothing. Sourced
# by the cluster's tests (netns_test.sh, netfault_test.sh); DIR is the run's --out folder, whose
# cluster.sh stderr is DIR.err.
# nothing_left DIR PIDS: no rank had to be killed by cluster.sh, no process of the run, no shared
# memory of PIDS.
nothing_left() {
  local dir=$1 pids=$2 p
  if grep -q "^cluster: left running" "$dir.err"; then
    echo "FAIL: processes left on a host:"
    grep "^cluster: left running" "$dir.err"
    exit 1
  fi
  if pgrep -af -- "$dir"; then echo "FAIL: processes of the run left"; exit 1; fi
  for p in $pids; do
    if compgen -G "/dev/shm/l2-$p-*" >/dev/null; then echo "FAIL: /dev/shm/l2-$p-* left"; exit 1; fi
  done
}
