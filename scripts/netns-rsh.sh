#!/usr/bin/env bash
# mpirun's remote-shell agent for the namespace cluster of scripts/cluster.sh: where ssh would
# log into HOST, this enters HOST's network namespace (its own network stack and address) with
# its own host name, and runs the command mpirun gives, as ssh's remote shell would (the words
# joined). Usage (by mpirun, --mca plm_rsh_agent): netns-rsh.sh HOST WORD...
set -euo pipefail
host=$1
shift
: "${L2_CLUSTER_PREFIX:?netns-rsh.sh: L2_CLUSTER_PREFIX is unset (run through scripts/cluster.sh)}"
exec ip netns exec "$L2_CLUSTER_PREFIX-$host" unshare --uts sh -c 'hostname "$1"; shift; exec sh -c "$*"' \
  sh "$host" "$@"
