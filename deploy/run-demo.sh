#!/usr/bin/env bash
# The main job: a real table-tennis match between two agent processes over LCM. Starts an
# olympics-server, plays a best-of-three match of games to 6 points (by 2) between two scripted
# players, prints the referee's calls (each point with its strokes: the rallies) and the result,
# stores it, writes the replay and its scene track, prints the results table and the command to
# watch the match, and stops the server. OLYMPICS_DEMO_SPORT and OLYMPICS_DEMO_OPTIONS play another
# sport (e.g. tennis with '{"format":"tiebreak"}'; the scripted tennis players seldom reach a
# ball, so a tennis tie-break can run to the time limit: docs/racket-sports.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin
[ -x "$bin/olympics-server" ] || bash deploy/build.sh
bash deploy/multicast-route.sh
url="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
db=${OLYMPICS_RESULTS:-olympics-results.db}
sport=${OLYMPICS_DEMO_SPORT:-table_tennis}
options=${OLYMPICS_DEMO_OPTIONS:-'{"games_to_win":2,"points_per_game":6}'}
mkdir -p replays
"$bin/olympics-server" serve --lcm-url "$url" --results "$db" --replay-dir replays --id demo_$$ \
  > demo-server.log 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null || true' EXIT
request="demo-$$-$(date +%s)"
# --server: the demo's own server hosts (and stores) the match, even with others on this URL
common=(--lcm-url "$url" --server "demo_$$" --request-id "$request" --sport "$sport" --mode 1v1 --seed 7
        --time-limit 180 --options "$options" --policy scripted)
"$bin/olympics-agent" "${common[@]}" --slots 0 --name ace > demo-agent0.log 2>&1 &
agent0=$!
"$bin/olympics-agent" "${common[@]}" --slots 1 --name volley --calls | tee demo-agent1.log
wait $agent0
match=$(sed -n 's/^match \([^ ]*\).*/\1/p' demo-agent1.log | head -1)
echo
echo "Stored in $db (olympics-server results --results $db):"
"$bin/olympics-server" results --results "$db" --limit 5
if [ -n "$match" ] && [ -f "replays/$match.scene" ]; then
  echo
  echo "Replay and scene track: replays/$match.replay, replays/$match.scene. Watch the match:"
  echo "  $bin/olympics-server view replays/$match.replay        # then open http://127.0.0.1:8080/"
  echo "  $bin/olympics-server view replays/$match.replay --export $match.html   # one shareable file"
fi
