# Sourced by the fleet's namespace tests: hosts on one LAN, each a network namespace with one veth
# link to a bridge, the address $net.(10 + its position in hosts), and a default route on that link.
# The test sets tag (unique names; interfaces have 15 characters), net (a /24 prefix), bridge,
# work (its folder) and hosts (the namespaces' names) before calling make_lan.

ns() { echo "$tag-$1"; }
in_ns() { local h=$1; shift; ip netns exec "$(ns "$h")" "$@"; }
fail() { echo "FAILED: $*"; keep_work=1; exit 1; }

# Kills every process in the hosts, removes them and the bridge; keeps $work after a failure.
lan_cleanup() {
  set +e
  for h in "${hosts[@]}"; do
    for pid in $(ip netns pids "$(ns "$h")" 2>/dev/null); do kill -9 "$pid" 2>/dev/null; done
    ip netns del "$(ns "$h")" 2>/dev/null
  done
  ip link del "$bridge" 2>/dev/null
  if [ "${keep_work:-0}" = 0 ]; then rm -rf "$work"; else echo "logs kept in $work"; fi
}

# Makes the bridge and the hosts (exit 77, skipped, where namespaces cannot be made).
make_lan() {
  trap lan_cleanup EXIT
  ip netns add "$(ns "${hosts[0]}")" 2>/dev/null || { echo "SKIPPED: ip netns add failed"; exit 77; }
  ip link add "$bridge" type bridge
  ip link set "$bridge" up
  local i=0 h
  for h in "${hosts[@]}"; do
    i=$((i + 1))
    ip netns list | grep -qw "$(ns "$h")" || ip netns add "$(ns "$h")"
    ip link add "v$tag$i" type veth peer name "p$tag$i"
    ip link set "p$tag$i" master "$bridge" up
    ip link set "v$tag$i" netns "$(ns "$h")"
    in_ns "$h" ip link set lo up
    in_ns "$h" ip addr add "$net.$((10 + i))/24" dev "v$tag$i"
    in_ns "$h" ip link set "v$tag$i" up
    in_ns "$h" ip route add default dev "v$tag$i"
  done
}
