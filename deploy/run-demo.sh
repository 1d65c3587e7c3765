#!/usr/bin/env bash
# The main job: a real match between two agent processes over LCM, its result printed and
# stored. Starts an olympics-server, plays a sandbox 1v1 (a zero-action agent against a random
# one), prints the result and the results table, and stops the server.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin
[ -x "$bin/olympics-server" ] || bash deploy/build.sh
bash deploy/multicast-route.sh
url="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
db=${OLYMPICS_RESULTS:-olympics-results.db}
mkdir -p replays
"$bin/olympics-server" serve --lcm-url "$url" --results "$db" --replay-dir replays --id demo-$$ \
  > demo-server.log 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null || true' EXIT
request="demo-$$-$(date +%s)"
"$bin/olympics-agent" --lcm-url "$url" --request-id "$request" --sport sandbox --mode 1v1 \
  --slots 0 --policy zero --name steady --seed 7 > demo-agent0.log 2>&1 &
agent0=$!
"$bin/olympics-agent" --lcm-url "$url" --request-id "$request" --sport sandbox --mode 1v1 \
  --slots 1 --policy random --name flailer --seed 7
wait $agent0
echo
echo "Stored in $db (olympics-server results --results $db):"
"$bin/olympics-server" results --results "$db" --limit 5
