#!/usr/bin/env bash
# A cluster on one machine: each host a Linux network namespace with its own address and host
# name, joined by a bridge, its link shaped to a rate if asked (tc tbf) or made to lose packets
# (nftables' random drop), or joined instead by the link emulator (tools/link_emulator: a switch
# between tap devices that holds every packet for a delay with jitter, as netem would, which
# this machine's kernel lacks), and a command run across
# the hosts with mpirun as on real machines (a hostfile, an rsh agent that enters the namespaces,
# the MPI interfaces pinned to the cluster's subnet). mpirun itself runs on the first host, as a
# user would on the head node. Everything made is removed when it ends, however it ends; names
# are unique to the run, so two runs at once do not meet. Needs root (CI is).
#
# Usage: scripts/cluster.sh [--hosts NAME:SLOTS,...] [--rate RATE] [--loss PERCENT]
#                           [--delay MS [--jitter MS]] [--link-emulator PATH] [--subnet A.B.C]
#                           [--keep-job] [--id ID] -- PROGRAM ARGS...
#        scripts/cluster.sh --link ID HOST cut|restore
#   --hosts    the hosts and how many ranks each takes, in rank order (default
#              render-a:3,render-b:2,display-a:1: the default wall's coordinator and
#              pipeservers 0-1, pipeservers 2-3, its board column)
#   --rate     each host's link, both ways: e.g. 1gbit, 10gbit, 500mbit (default: unshaped)
#   --loss     each host's link drops this share of its packets at random, both ways: 0 < PERCENT
#              < 100, one decimal at most (e.g. 1, 0.5); a packet between two hosts crosses two
#              links, so about twice PERCENT of them are lost end to end (nftables' numgen random)
#   --delay    every packet a host sends is held MS milliseconds (e.g. 5, 0.5) before it reaches
#              the host it is for, as `tc netem delay MS` on every host's link: the hosts are
#              joined by the link emulator, not the bridge (not with --rate)
#   --jitter   with --delay: each packet's hold drawn uniformly from the delay ± MS, never below
#              0, so packets overtake each other as under netem (default 0)
#   --link-emulator PATH
#              the link emulator program (default: build/default/tools/link_emulator/link_emulator)
#   --subnet   the hosts' /24, host i at .(i+2) (default 10.213.7; only inside the namespaces)
#   --keep-job mpirun keeps the job when a rank dies (--mca orte_enable_recovery 1 --mca
#              orte_abort_on_non_zero_status 0), as `l2wall run --mpi --survive-host-loss` needs;
#              its exit code then says nothing of the run: 0 whatever the ranks did, and 1 when
#              l2wall ended it after a run that lost a rank (it says so: "ending the job"), a
#              run that survived included. The run's outcome is l2wall's last line and the first
#              line of its summary.txt.
#   --id       the cluster's name, a-z then a-z/0-9, 8 at most (default: l2c + 5 random hex
#              digits): host HOST is network namespace ID-HOST, so that another shell can act on
#              it while the command runs; refused if a namespace of that name exists
#   --link ID HOST cut|restore
#              while cluster ID runs: cut HOST's link (every packet in or out, loopback aside,
#              dropped in silence, as a pulled cable or a dead switch port: no connection is
#              told) or restore it; exits 1 with a line if ID-HOST is not there
# It runs: mpirun -np <the slots' sum> --hostfile ... PROGRAM ARGS..., prints that command on
# one line ("cluster: ..."), with --loss a last line of what the links dropped ("cluster: --loss 1:
# the hosts' links dropped 37 of 3815 packets"), with --delay one of what the link emulator
# carried and how long it held each ("cluster: link_emulator: 52310 frames ... held 0.0 to
# 10.3 ms, mean 5.02 ms; dropped ..."), and exits with its code; 77 when this machine cannot make network
# namespaces (not root, no ip netns), said in one line. Open MPI's own lines that -q does not
# reach and that say nothing wrong of the run here are left out of its stderr (noise() below).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
hosts_spec=render-a:3,render-b:2,display-a:1 rate= loss= subnet=10.213.7 keep_job=() id=
delay= jitter= emulator=$here/../build/default/tools/link_emulator/link_emulator emulator_pid=
usage() { sed -n '/^# Usage:/,/^set /p' "$0" | sed '$d; s/^# \{0,1\}//'; }
while (($#)); do
  case $1 in
    --hosts) hosts_spec=${2:?--hosts needs NAME:SLOTS,...}; shift 2 ;;
    --rate) rate=${2:?--rate needs a rate such as 1gbit}; shift 2 ;;
    --loss) loss=${2:?--loss needs a percentage such as 1}; shift 2 ;;
    --delay) delay=${2:?--delay needs milliseconds such as 5}; shift 2 ;;
    --jitter) jitter=${2:?--jitter needs milliseconds such as 5}; shift 2 ;;
    --link-emulator) emulator=${2:?--link-emulator needs a path}; shift 2 ;;
    --subnet) subnet=${2:?--subnet needs A.B.C}; shift 2 ;;
    --id) id=${2:?--id needs a name}; shift 2 ;;
    --link) shift; exec bash "$here/cluster-link.sh" "$@" ;;
    --keep-job) keep_job=(--mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0); shift ;;
    -h | --help) usage; exit 0 ;;
    --) shift; break ;;
    *) echo "cluster.sh: unknown option '$1' (--help lists them)" >&2; exit 2 ;;
  esac
done
(($#)) || { echo "cluster.sh: no command after -- (--help)" >&2; exit 2; }
[[ $subnet =~ ^[0-9]{1,3}\.[0-9]{1,3}\.[0-9]{1,3}$ ]] ||
  { echo "cluster.sh: --subnet '$subnet' is not A.B.C" >&2; exit 2; }
if [[ -n $rate && ! $rate =~ ^[0-9]+[kmg]bit$ ]]; then
  echo "cluster.sh: --rate '$rate' is not N followed by kbit, mbit or gbit" >&2
  exit 2
fi
if [[ -n $loss ]] && ! [[ $loss =~ ^[0-9]{1,2}(\.[0-9])?$ && ${loss/./} =~ [1-9] ]]; then
  echo "cluster.sh: --loss '$loss' is not a percentage above 0 and below 100 (one decimal at most)" >&2
  exit 2
fi
# Milliseconds: at most 10000, three decimals at most.
milliseconds() { [[ $1 =~ ^[0-9]{1,5}(\.[0-9]{1,3})?$ ]] && awk -v t="$1" 'BEGIN { exit !(t <= 10000) }'; }
if [[ -n $delay ]] && ! { milliseconds "$delay" && [[ $delay =~ [1-9] ]]; }; then
  echo "cluster.sh: --delay '$delay' is not milliseconds above 0 and at most 10000 (e.g. 5, 0.5)" >&2
  exit 2
fi
if [[ -n $jitter ]] && ! milliseconds "$jitter"; then
  echo "cluster.sh: --jitter '$jitter' is not milliseconds from 0 to 10000 (e.g. 5, 0.5)" >&2
  exit 2
fi
if [[ -n $jitter && -z $delay ]]; then
  echo "cluster.sh: --jitter needs --delay (the jitter is around the delay)" >&2
  exit 2
fi
if [[ -n $delay && -n $rate ]]; then
  echo "cluster.sh: --delay and --rate cannot be combined: the link emulator does not shape links" >&2
  exit 2
fi
if [[ -n $delay && ! -x $emulator ]]; then
  echo "cluster.sh: --delay needs the link emulator, not at $emulator (cmake --build --preset default, or --link-emulator PATH)" >&2
  exit 2
fi
if [[ -n $id && ! $id =~ ^[a-z][a-z0-9]{0,7}$ ]]; then
  echo "cluster.sh: --id '$id' is not a-z then a-z or 0-9, 8 at most" >&2
  exit 2
fi
names=() slots=()
IFS=, read -ra entries <<<"$hosts_spec"
for e in "${entries[@]}"; do
  [[ $e =~ ^([a-z][a-z0-9-]{0,20}):([1-9][0-9]*)$ ]] ||
    { echo "cluster.sh: --hosts entry '$e' is not NAME:SLOTS (name: a-z, 0-9, -)" >&2; exit 2; }
  names+=("${BASH_REMATCH[1]}") slots+=("${BASH_REMATCH[2]}")
done

if [[ -n $id ]] && ip netns list 2>/dev/null | grep -q "^$id-"; then
  echo "cluster.sh: --id '$id': a cluster of that name runs (ip netns list)" >&2
  exit 2
fi
id=${id:-l2c$(printf '%05x' $((RANDOM * 32 + RANDOM % 32)))}
if ! ip netns add "$id-probe" 2>/dev/null; then
  echo "cluster.sh: cannot make network namespaces here (root and iproute2's ip netns needed)" >&2
  exit 77
fi
ip netns del "$id-probe"
# The hostfile, and every host's Open MPI session folders (orte_tmpdir_base below): each daemon
# leaves its host's folder behind when it ends, and in /tmp they would meet another mpirun's
# (every mpirun on a machine shares its host's folder). Short: PMIx's socket paths go under it.
work=$(mktemp -d /tmp/l2mpi.XXXXXX)
# Processes still on a host once the command has ended are named (a run must leave none: give
# them 10 s to exit) and killed, at once when this script was interrupted; then the namespaces,
# links and bridge go.
cleanup() {
  local h pids waited
  for ((waited = 0; waited < 100 && !interrupted; ++waited)); do
    pids=$(for h in "${names[@]}"; do ip netns pids "$id-$h" 2>/dev/null || true; done)
    [[ -n $pids ]] || break
    sleep 0.1
  done
  for h in "${names[@]}"; do
    pids=$(ip netns pids "$id-$h" 2>/dev/null || true)
    [[ -z $pids ]] && continue
    echo "cluster: left running on $h, killed: $(ps -o comm= -p "${pids//$'\n'/,}" | sort | uniq -c | xargs)" >&2
    kill -9 $pids 2>/dev/null || true
  done
  [[ -z $loss ]] || say_losses
  [[ -z $emulator_pid ]] || say_held
  for h in "${names[@]}"; do ip netns del "$id-$h" 2>/dev/null || true; done
  # Links not yet moved into a namespace when the setup failed.
  for h in "${!names[@]}"; do ip link del "${id}h$h" 2>/dev/null || true; done
  ip link del "${id}br" 2>/dev/null || true
  rm -rf "$work"
}
# --loss: what the links dropped of what they carried, from the rules' counters (both ways, every
# host), so that a run can show its packets were lost.
say_losses() {
  local h counts
  counts=$(for h in "${names[@]}"; do ip netns exec "$id-$h" nft list table inet l2loss 2>/dev/null; done |
    awk '/counter packets/ { for (i = 1; i < NF; ++i) if ($i == "packets") n = $(i + 1);
                             if (/drop/) dropped += n; else seen += n }
         END { printf "%d %d", dropped, seen }')
  echo "cluster: --loss $loss: the hosts' links dropped ${counts% *} of ${counts#* } packets"
}
# --delay: the link emulator ended and its last line (what it carried, held and dropped) shown.
say_held() {
  kill -TERM "$emulator_pid" 2>/dev/null || true
  wait "$emulator_pid" 2>/dev/null || true
  echo "cluster: $(tail -1 "$work/link_emulator.out")"
}
interrupted=0
trap cleanup EXIT
trap 'interrupted=1; exit 130' INT TERM

# A token bucket, both ways, on a link's two ends: its burst one millisecond of the rate.
shape() {  # shape NETNS-OR-"" DEVICE
  local bits=${rate%bit} scale=1
  case ${bits: -1} in k) scale=1000 ;; m) scale=1000000 ;; g) scale=1000000000 ;; esac
  local burst=$(( ${bits%?} * scale / 8 / 1000 ))
  ((burst >= 16384)) || burst=16384
  ip ${1:+-n "$1"} link set "$2" txqueuelen 10000 2>/dev/null || true
  tc ${1:+-n "$1"} qdisc add dev "$2" root tbf rate "$rate" burst "$burst" latency 100ms
}

# PERCENT of a link's packets dropped at random, each way: in thousandths, numgen's range.
lossy() {  # lossy NETNS
  local whole=${loss%.*} tenths=0
  [[ $loss == *.* ]] && tenths=${loss#*.}
  local per_mille=$((10#$whole * 10 + tenths))
  ip netns exec "$1" nft -f - <<NFT
table inet l2loss {
  chain in { type filter hook input priority 0; iifname "lo" accept; counter; numgen random mod 1000 < $per_mille counter drop; }
  chain out { type filter hook output priority 0; oifname "lo" accept; counter; numgen random mod 1000 < $per_mille counter drop; }
}
NFT
}

if [[ -n $loss ]] && ! command -v nft >/dev/null; then
  echo "cluster.sh: --loss needs nftables' nft (apt-get install nftables)" >&2
  exit 2
fi
# The hosts' links: veth pairs joined by a bridge, or with --delay tap devices whose other ends
# the link emulator holds. It attaches to them here, before they move into the hosts'
# namespaces, where their names are no longer seen from here.
if [[ -z $delay ]]; then
  ip link add "${id}br" type bridge
  ip link set "${id}br" up
fi
for i in "${!names[@]}"; do
  ip netns add "$id-${names[$i]}"
  if [[ -n $delay ]]; then
    ip tuntap add dev "${id}h$i" mode tap
  else
    ip link add "${id}h$i" type veth peer name "${id}b$i"
    ip link set "${id}b$i" master "${id}br"
    ip link set "${id}b$i" up
  fi
done
if [[ -n $delay ]]; then
  taps=()
  for i in "${!names[@]}"; do taps+=(--tap "${id}h$i"); done
  "$emulator" "${taps[@]}" --delay "$delay" --jitter "${jitter:-0}" >"$work/link_emulator.out" &
  emulator_pid=$!
  for _ in $(seq 100); do
    grep -q '^link_emulator: ready$' "$work/link_emulator.out" && break
    kill -0 "$emulator_pid" 2>/dev/null || break
    sleep 0.1
  done
  grep -q '^link_emulator: ready$' "$work/link_emulator.out" ||
    { echo "cluster: the link emulator did not start" >&2; emulator_pid=; exit 1; }
fi
: >"$work/hostfile"
for i in "${!names[@]}"; do
  ns=$id-${names[$i]}
  ip link set "${id}h$i" netns "$ns"
  ip -n "$ns" link set lo up
  ip -n "$ns" addr add "$subnet.$((i + 2))/24" dev "${id}h$i"
  ip -n "$ns" link set "${id}h$i" up
  if [[ -n $rate ]]; then shape "$ns" "${id}h$i"; shape "" "${id}b$i"; fi
  if [[ -n $loss ]]; then lossy "$ns"; fi
  echo "${names[$i]} slots=${slots[$i]}" >>"$work/hostfile"
  np=$((${np:-0} + slots[i]))
done

export L2_CLUSTER_PREFIX=$id OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# hwloc's GL plugin would open X display :0 in every rank.
export HWLOC_COMPONENTS=-gl
# Every host is this machine: their ranks share its cores, more ranks than cores, which the
# hostfile's slots hide from Open MPI; a waiting rank must yield its core, not busy-poll it.
mpirun=(mpirun -q -np "$np" --hostfile "$work/hostfile" --map-by slot
  --mca orte_tmpdir_base "$work" --mca plm_rsh_agent "$here/netns-rsh.sh" --mca btl self,tcp
  --mca btl_tcp_if_include "$subnet.0/24" --mca oob_tcp_if_include "$subnet.0/24"
  --mca mpi_yield_when_idle 1 "${keep_job[@]}")
echo "cluster: ${#names[@]} hosts (${hosts_spec//,/ }, namespaces $id-HOST) on $subnet.0/24${rate:+, links at $rate}${loss:+, $loss % loss each way}${delay:+, each packet held $delay${jitter:+ ± $jitter} ms by the link emulator}: ${mpirun[*]} $*"
# Open MPI 4.1's lines that -q does not reach, each harmless here: the
# rsh launcher cannot move a namespace's agent into its own process group (the agent is ended
# with the job all the same); PMIx reports a bad parameter of its event notification when a job
# keeps going after a rank's end (--keep-job); its event library warns of a descriptor already
# closed by a rank that ended. Every other line of mpirun and the program passes.
noise() {
  grep --line-buffered -v -E \
    -e '^\[[^]]+\] plm:rsh: Warning: setpgid\([0-9]+,[0-9]+\) failed in parent with errno=Permission denied\(13\)$' \
    -e '^\[[^]]+\] PMIX ERROR: BAD-PARAM in file [^ ]*pmix_event_notification\.c at line [0-9]+$' \
    -e '^\[warn\] Epoll MOD\([0-9]+\) on fd [0-9]+ failed\.' >&2 || true
}
# In the background and waited for: a signal to this script is then taken at once (bash runs a
# trap only after a foreground command ends), and the cleanup ends the run on every host. The
# subshell ends once its stderr has gone through noise() whole, with mpirun's status (pipefail).
(ip netns exec "$id-${names[0]}" unshare --uts sh -c 'hostname "$1"; shift; exec "$@"' \
  sh "${names[0]}" "${mpirun[@]}" "$@" 2>&1 >&3 3>&- | noise) 3>&1 &
status=0
wait $! || status=$?
exit "$status"
