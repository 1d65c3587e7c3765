#!/usr/bin/env bash
# A learner spread over two cells, losing one (docs/deploy.md, "Remote learners"): network
# namespaces on a bridge stand for a learner host and two cell hosts, each cell an olympics-server
# and `olympics-relay listen`; on the learner host one `olympics-relay connect` per cell (each on
# its own learner-side LCM port) and a CellsVectorEnv of 2 tennis matches per cell. Once it steps,
# every process of cell B is killed (SIGKILL). The learner must keep stepping, its 2 matches on
# cell B reported lost (with their match ids, not a hang, not an exception), cell A's own 2
# matches go on, and all 4 environments play on cell A afterwards.
#
#   tests/fleet/learner_cells_test.sh BIN_DIR
#
# Needs root (namespaces) and the Python package in BIN_DIR/../python; exits 77 (ctest: skipped,
# and says why) without them.
set -euo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
if [ "$(id -u)" != 0 ]; then
  echo "SKIPPED: this test needs root to make network namespaces (run it as root, or in CI)"
  exit 77
fi
pypath=$(cd "$bin/../python" 2>/dev/null && pwd || true)
if [ -z "$pypath" ] || ! PYTHONPATH=$pypath $python -c "import smpl_olympics._client" 2>/dev/null; then
  echo "SKIPPED: the Python package is not built in $bin/../python (clients/python/install.sh)"
  exit 77
fi
tag=l$$
net=10.$((100 + $$ % 50)).$(($$ % 250))
bridge=br$tag
work=$(mktemp -d /tmp/learner-cells-test-XXXXXX)
chmod 755 "$work"
hosts=(a b learner)
source "$(dirname "$0")/lan.sh"
make_lan

"$bin/olympics-server" secret "$work/secret" > /dev/null
port=7701
urls=()
for h in a b; do
  # Room for 4 matches: its own 2, and cell b's 2 should b be lost. A learner's server waits for
  # its actions (as a private server does): the step that finds the loss waits ~5 s for it, and
  # the other cell's matches must not be forfeited meanwhile.
  in_ns "$h" "$bin/olympics-server" serve --id "cell_$h" --capacity 4 --secret "$work/secret" \
    --silent-timeout-s 600 --action-deadline-ms 600000 --max-missed-ticks 100000 \
    --results "$work/results-$h.db" > "$work/server-$h.log" 2>&1 &
  in_ns "$h" "$bin/olympics-relay" listen --port 7700 --secret "$work/secret" \
    > "$work/relay-$h.log" 2>&1 &
done
sleep 1
ip_a=$net.11 ip_b=$net.12
for h in a b; do
  url="udpm://239.255.76.67:$port?ttl=0"
  ip=ip_$h
  in_ns learner "$bin/olympics-relay" connect --to "${!ip}:7700" --lcm-url "$url" \
    --secret "$work/secret" > "$work/relay-learner-$h.log" 2>&1 &
  urls+=("$url")
  port=$((port + 1))
done
sleep 1
in_ns learner env PYTHONPATH="$pypath" $python "$here/cells_learner.py" "$work/secret" "$work" \
  "${urls[@]}" > "$work/learner.json" 2> "$work/learner.log" &
learner=$!

steps() { awk '{print $1}' "$work/learner-steps" 2>/dev/null || echo 0; }
wait_steps() {  # wait_steps N SECONDS
  local until=$((SECONDS + $2))
  while [ "$(steps)" -lt "$1" ]; do
    [ $SECONDS -lt $until ] || fail "the learner has $(steps) steps, not $1: $(tail -3 "$work/learner.log")"
    kill -0 $learner 2>/dev/null || fail "the learner stopped: $(tail -5 "$work/learner.log")"
    sleep 0.2
  done
}
wait_steps 100 60
before=$(steps)
for pid in $(ip netns pids "$(ns b)"); do kill -9 "$pid" 2>/dev/null || true; done
killed_at=$SECONDS
wait_steps $((before + 300)) 90
touch "$work/stop"
wait $learner || fail "the learner failed: $(tail -5 "$work/learner.log")"
lost_after_s=$((SECONDS - killed_at))

summary=$($python - "$work/learner.json" "${urls[0]}" "${urls[1]}" <<'PY'

import json, sys
s = json.load(open(sys.argv[1]))
a, b = sys.argv[2], sys.argv[3]
def fail(why):
    print(f"FAILED: {why}: {json.dumps(s)}")
    sys.exit(1)
lost = s["lost_matches"]
if sorted(m["env"] for m in lost) != [2, 3] or any(m["cell"] != b for m in lost):
    fail("cell b's environments 2 and 3 should be reported lost, and only they")
if not all(m["match_id"] and m["error"].startswith(("SERVER_GONE", "TIMEOUT")) for m in lost):
    fail("each lost match should name its match and why")
if s["cells_now"] != [a] * 4:
    fail("every environment should play on cell a after the loss")
if min(s["ticks"][:2]) < s["steps"] - 10:
    fail("cell a's own matches should have gone on through the loss, not restarted")
if s["steps_after_loss"] < 200:
    fail("the learner did not keep stepping after the loss")
print(f"{s['steps']} steps, {s['steps_after_loss']} after the loss; lost "
      + ", ".join(f"env {m['env']} match {m['match_id']} ({m['error'].split(':')[0]})" for m in lost)
      + f"; the step that found the loss took {s['longest_step_s']} s; ticks at the end {s['ticks']}")
PY
) || { echo "$summary"; keep_work=1; exit 1; }
echo "PASSED: a learner over 2 cells (2 tennis matches each, one relay per cell); cell b killed (SIGKILL, every process) after $before steps; the learner went on: $summary"
