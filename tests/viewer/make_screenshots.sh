#!/usr/bin/env bash
# Makes docs/screenshots/<sport>.png: a short scripted 1v1 of each sport on a real server,
# exported with `olympics-server view --export`, one frame captured by headless Chromium.
# Usage: [SPORTS="soccer ..."] tests/viewer/make_screenshots.sh [build/bin] [frame]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/bin}
frame=${2:-100}
work=$(mktemp -d)
url="udpm://239.255.76.67:$((26000 + $$ % 9000))?ttl=0&recv_buf_size=4194304"
"$bin/olympics-server" serve --lcm-url "$url" --results "$work/r.db" --replay-dir "$work" \
  --id shots > "$work/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null || true' EXIT
mkdir -p docs/screenshots
for sport in ${SPORTS:-tennis table_tennis fencing boxing sandbox soccer}; do
  policy=scripted
  [ "$sport" = sandbox ] && policy=random   # no scripted player for the test sport
  pids=()
  for slot in 0 1; do
    "$bin/olympics-agent" --lcm-url "$url" --request-id "shot-$sport" --sport "$sport" \
      --mode 1v1 --seed 3 --time-limit 8 --policy $policy --slots $slot --name "p$slot" \
      --json > "$work/$sport-$slot.json" &
    pids+=($!)
  done
  wait "${pids[@]}"
  match=$(python3 -c "import json,sys; print(json.loads(open(sys.argv[1]).read().splitlines()[-1])['match_id'])" "$work/$sport-0.json")
  "$bin/olympics-server" view "$work/$match.replay" --export "$work/$sport.html" > /dev/null
  chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
    --hide-scrollbars --window-size=960,600 --virtual-time-budget=8000 \
    --user-data-dir="$work/profile" --screenshot="docs/screenshots/$sport.png" \
    "file://$work/$sport.html?frame=$frame&camera=broadcast" 2> /dev/null
  echo "docs/screenshots/$sport.png: $match, frame $frame"
done
