#!/usr/bin/env bash
# A learner on another host plays on a cell through olympics-relay (docs/deploy.md, "Remote
# learners"): two network namespaces on a bridge, a cell host (olympics-server and `olympics-relay
# listen`) and a learner host (`olympics-relay connect`, then a league whose policy workers run on
# the learner host). The same tournament is played once from inside the cell and once from the
# learner host: the tables must be identical; the wall time of each is printed (what the relay
# costs). A relay with another secret is refused and says so.
#
#   tests/fleet/remote_learner_test.sh BIN_DIR     # RELAY_SPORT=tennis RELAY_TIME_LIMIT=5 (s)
#
# Needs root (namespaces); exits 77 (ctest: skipped, and says why) without it.
set -euo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR}" && pwd)
sport=${RELAY_SPORT:-tennis}
time_limit=${RELAY_TIME_LIMIT:-5}
if [ "$(id -u)" != 0 ]; then
  echo "SKIPPED: this test needs root to make network namespaces (run it as root, or in CI)"
  exit 77
fi
tag=r$$
net=10.$((150 + $$ % 50)).$(($$ % 250))
bridge=br$tag
hosts=(cell learner)
work=$(mktemp -d /tmp/relay-test-XXXXXX)
source "$(dirname "$0")/lan.sh"
make_lan
cell_ip=$net.11

"$bin/olympics-server" secret "$work/secret" > /dev/null
"$bin/olympics-server" secret "$work/other" > /dev/null
in_ns cell "$bin/olympics-server" serve --id cell --secret "$work/secret" \
  --results "$work/results.db" > "$work/server.log" 2>&1 &
in_ns cell "$bin/olympics-relay" listen --port 7700 --secret "$work/secret" \
  > "$work/relay-cell.log" 2>&1 &
sleep 1

# Another secret: refused, saying why; and the cell's relay goes on.
if in_ns learner "$bin/olympics-relay" connect --to "$cell_ip:7700" --secret "$work/other" \
  > "$work/intruder.log" 2>&1; then fail "a relay with another secret was admitted"; fi
grep -q "does not hold this deployment's secret" "$work/intruder.log" ||
  fail "the refused relay did not say why: $(cat "$work/intruder.log")"

league() {  # league HOST NAME: a round robin of four bots, from HOST, timed
  local h=$1 name=$2 start
  start=$(date +%s.%N)
  in_ns "$h" "$bin/olympics-league" run --db "$work/$name.db" --name "$name" --sport "$sport" \
    --entrants zero,random:1,random:2,zero --seed 4 --time-limit "$time_limit" --parallel 2 \
    --secret "$work/secret" --log-dir "$work" --quiet > "$work/$name.log" 2>&1 ||
    fail "the league on $h failed: $(tail -5 "$work/$name.log")"
  echo "$(date +%s.%N) - $start" | bc
}
inside=$(league cell inside)
# (ip netns exec directly, not in_ns: $! is then the relay itself, which SIGTERM stops.)
ip netns exec "$(ns learner)" "$bin/olympics-relay" connect --to "$cell_ip:7700" \
  --secret "$work/secret" > "$work/relay-learner.log" 2>&1 &
relay=$!
sleep 1
remote=$(league learner remote)
# The trainer's Python vector environment, inside the cell and through the relay (when the
# Python package is built): it must step there; its speed is printed, not judged.
pypath=$(cd "$bin/../python" 2>/dev/null && pwd || true)
vector=""
if [ -n "$pypath" ] && PYTHONPATH=$pypath /usr/bin/python3 -c "import smpl_olympics._client" 2>/dev/null; then
  bench=$(cd "$(dirname "$0")/../../benchmarks" && pwd)/relay_vector_bench.py
  for h in cell learner; do
    in_ns "$h" env PYTHONPATH="$pypath" /usr/bin/python3 "$bench" 4 200 "$work/secret" \
      > "$work/vector-$h.log" 2>&1 || fail "the vector env on the $h host: $(tail -3 "$work/vector-$h.log")"
  done
  vector=" Vector env, 4 tennis matches: inside the cell $(tail -1 "$work/vector-cell.log"); through the relay $(tail -1 "$work/vector-learner.log")."
else
  vector=" (Python package not built: the vector env was not run)"
fi
kill -TERM $relay
wait $relay || true
in_ns cell "$bin/olympics-league" table --db "$work/inside.db" --name inside --json > "$work/a.json"
in_ns cell "$bin/olympics-league" table --db "$work/remote.db" --name remote --json > "$work/b.json"
cmp -s "$work/a.json" "$work/b.json" || fail "tables differ: $(diff "$work/a.json" "$work/b.json")"
ticks=$(sqlite3 "$work/remote.db" "SELECT sum(ticks) FROM games")
printf "PASSED: 6 %s games (%s ticks): from inside the cell %.1f s, from the learner host through the relay %.1f s (%.2fx); the same table; another secret refused. %s%s\n" \
  "$sport" "$ticks" "$inside" "$remote" "$(echo "$remote / $inside" | bc -l)" \
  "$(tail -1 "$work/relay-learner.log")" "$vector"
