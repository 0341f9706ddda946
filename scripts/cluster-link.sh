#!/usr/bin/env bash
# Cuts or restores one host's link in a running cluster of scripts/cluster.sh (its --link mode):
# a cut drops every packet in and out of the host's namespace but loopback's, in silence, as a
# pulled cable or a dead switch port would (no connection is told, no route goes away); restore
# takes the rule out. Its packets lost meanwhile are sent again by TCP as on a real network.
# Usage: scripts/cluster.sh --link ID HOST cut|restore
set -euo pipefail
(($# == 3)) || { echo "cluster.sh --link: needs ID HOST cut|restore" >&2; exit 2; }
id=$1 host=$2 action=$3
ns=$id-$host
[[ $id =~ ^[a-z][a-z0-9]{0,7}$ && $host =~ ^[a-z][a-z0-9-]{0,20}$ ]] ||
  { echo "cluster.sh --link: '$id' '$host' are not a cluster's id and host" >&2; exit 2; }
[[ $action == cut || $action == restore ]] ||
  { echo "cluster.sh --link: '$action' is not cut or restore" >&2; exit 2; }
ip netns list 2>/dev/null | grep -q "^$ns\b" ||
  { echo "cluster.sh --link: no host $host in cluster $id (no namespace $ns)" >&2; exit 1; }
case $action in
  cut)
    ip netns exec "$ns" nft -f - <<'NFT'
table inet l2cut {
  chain in { type filter hook input priority -10; iifname "lo" accept; drop; }
  chain out { type filter hook output priority -10; oifname "lo" accept; drop; }
}
NFT
    ;;
  restore) ip netns exec "$ns" nft delete table inet l2cut ;;
esac
