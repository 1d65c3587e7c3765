#!/usr/bin/env bash
# LCM's udpm transport needs a route for multicast. Most machines have one through the default
# route; an isolated machine or container may have none, and then every LCM program fails to
# start. Adds one on the loopback interface when it is missing (needs root).
set -euo pipefail
if ip route get 239.255.76.67 >/dev/null 2>&1; then exit 0; fi
as_root=()
if [ "$(id -u)" != 0 ]; then as_root=(sudo); fi
"${as_root[@]}" ip link set lo multicast on
"${as_root[@]}" ip route add 224.0.0.0/4 dev lo
echo "added a multicast route on lo for LCM"
