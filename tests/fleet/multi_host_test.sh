#!/usr/bin/env bash
# The league across hosts, with faults (docs/deploy.md, issue 32): network namespaces with their
# own addresses on one bridge stand for machines: one PostgreSQL host and three cell hosts, each
# cell one olympics-server and its policy workers on LCM's default URL (ttl=0). A round robin is
# queued; one cell is killed (every process of its host, SIGKILL) while it holds a game, another
# is cut off (its link down) for some seconds. The test checks that every fixture is stored
# exactly once, that the table is the table of the same tournament played on one host, that the
# cut-off cell paused and went on, and that no LCM datagram left a cell (a listener on the
# database host that does hear a ttl=1 datagram sent as a control).
#
#   tests/fleet/multi_host_test.sh BIN_DIR   # FLEET_ENTRANTS=21 (210 games), FLEET_CUT_S=20 s
#
# Needs root (namespaces, a bridge, a PostgreSQL of its own run as user postgres); exits 77
# (ctest: skipped, and says why) without it.
set -euo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR}" && pwd)
entrants=${FLEET_ENTRANTS:-21}     # a round robin of n entrants: n(n-1)/2 games (210)
cut_s=${FLEET_CUT_S:-20}            # how long the cut-off cell's link is down
lease_s=${FLEET_LEASE_S:-5}
time_limit=${FLEET_TIME_LIMIT:-1}  # seconds per sandbox match
deadline_s=${FLEET_DEADLINE_S:-240}

if [ "$(id -u)" != 0 ]; then
  echo "SKIPPED: this test needs root to make network namespaces (run it as root, or in CI)"
  exit 77
fi
pgbin=/usr/lib/postgresql/$(ls /usr/lib/postgresql | sort -n | tail -1)/bin
[ -x "$pgbin/postgres" ] || { echo "SKIPPED: no PostgreSQL server in /usr/lib/postgresql"; exit 77; }
python=/usr/bin/python3

tag=f$$                      # names unique to this run (interfaces have 15 characters)
net=10.$((200 + $$ % 50)).$(($$ % 250))
bridge=br$tag
work=$(mktemp -d /tmp/fleet-test-XXXXXX)
chmod 755 "$work"
hosts=(db cell1 cell2 cell3 solo learner)
ns() { echo "$tag-$1"; }
in_ns() { local h=$1; shift; ip netns exec "$(ns "$h")" "$@"; }

cleanup() {
  set +e
  for h in "${hosts[@]}"; do
    if ip netns list | grep -qw "$(ns "$h")"; then
      for pid in $(ip netns pids "$(ns "$h")"); do kill -9 "$pid" 2>/dev/null; done
      ip netns del "$(ns "$h")"
    fi
  done
  ip link del "$bridge" 2>/dev/null
  if [ "${keep_work:-0}" = 0 ]; then rm -rf "$work"; else echo "logs kept in $work"; fi
}
trap cleanup EXIT
fail() { echo "FAILED: $*"; keep_work=1; exit 1; }

if ! ip netns add "$(ns db)" 2>/dev/null; then
  echo "SKIPPED: network namespaces cannot be made here (ip netns add failed)"
  exit 77
fi
ip link add "$bridge" type bridge
ip link set "$bridge" type bridge mcast_snooping 0  # flood multicast: a leak would be heard
ip addr add "$net.1/24" dev "$bridge"
ip link set "$bridge" up

# A host: a namespace with one link to the bridge, its address, and a default route through it,
# as a machine on a LAN (multicast finds its way out, unless ttl=0 keeps it in).
index=0
add_host() {
  local h=$1 address=$2
  index=$((index + 1))
  ip netns list | grep -qw "$(ns "$h")" || ip netns add "$(ns "$h")"
  ip link add "v$tag$index" type veth peer name "p$tag$index"
  ip link set "p$tag$index" master "$bridge" up
  ip link set "v$tag$index" netns "$(ns "$h")"
  in_ns "$h" sysctl -qw net.ipv6.conf.all.disable_ipv6=1
  in_ns "$h" ip link set lo up
  in_ns "$h" ip link set "v$tag$index" name eth0
  in_ns "$h" ip addr add "$address/24" dev eth0
  in_ns "$h" ip link set eth0 up
  in_ns "$h" ip route add default via "$net.1"
  echo "p$tag$index" > "$work/$h.link"
}
add_host db "$net.10"
add_host cell1 "$net.11"
add_host cell2 "$net.12"
add_host cell3 "$net.13"
add_host solo "$net.20"
add_host learner "$net.30"

# The PostgreSQL host: a cluster of its own, reachable from the bridge's network only.
mkdir "$work/pg" && chown postgres "$work/pg"
runuser -u postgres -- "$pgbin/initdb" -D "$work/pg" -A trust -U olympics >/dev/null
echo "host all all $net.0/24 trust" >> "$work/pg/pg_hba.conf"
in_ns db runuser -u postgres -- "$pgbin/postgres" -D "$work/pg" -k "$work/pg" \
  -c listen_addresses="$net.10" -c max_connections=60 > "$work/postgres.log" 2>&1 &
for _ in $(seq 100); do "$pgbin/pg_isready" -q -h "$net.10" && break; sleep 0.2; done
"$pgbin/pg_isready" -q -h "$net.10" || fail "PostgreSQL did not start: $(tail -5 "$work/postgres.log")"
db="postgresql://olympics@$net.10:5432/postgres"
sql() { psql -qAt "$db" -c "$1"; }

# A listener on the database host for LCM's group and port; a ttl=1 datagram from cell1 shows
# that it would hear one that left a cell.
in_ns db $python - "$work/heard" "$net.10" <<'EOF' &
import signal, socket, struct, sys
out, address = sys.argv[1], sys.argv[2]
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("239.255.76.67", 7667))
s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
             struct.pack("4s4s", socket.inet_aton("239.255.76.67"), socket.inet_aton(address)))
heard = 0
def stop(*_):
    open(out, "w").write(str(heard)); sys.exit(0)
signal.signal(signal.SIGTERM, stop)
open(out, "w").write("0")
while True:
    s.recv(65536); heard += 1
    open(out, "w").write(str(heard))
EOF
listener=$!
sleep 0.5
in_ns cell1 $python -c '
import socket; s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 1)
s.sendto(b"control", ("239.255.76.67", 7667))'
sleep 0.5
[ "$(cat "$work/heard")" = 1 ] || fail "the listener did not hear the ttl=1 control datagram"

# The deployment's secret, as every host of a real fleet has it.
"$bin/olympics-server" secret "$work/secret" > /dev/null
list=zero
for i in $(seq 2 "$entrants"); do list+=",random:$i"; done
games=$((entrants * (entrants - 1) / 2))
name=fleet$$
"$bin/olympics-league" run --fleet --db "$db" --name "$name" --entrants "$list" --seed 5 \
  --time-limit "$time_limit" --secret "$work/secret" > "$work/queue.log" 2>&1 || fail "queueing: $(cat "$work/queue.log")"

wait_for() {  # wait_for WHAT SECONDS CONDITION...
  local what=$1 seconds=$2; shift 2
  for _ in $(seq $((seconds * 5))); do "$@" && return 0; sleep 0.2; done
  fail "waited ${seconds}s for $what"
}
start_cell() {
  local h=$1
  shift
  mkdir -p "$work/$h"
  in_ns "$h" "$bin/olympics-league" cell --db "$db" --name "$name" --cell "$h" --spawn-server "$@" \
    --batch 2 --parallel 2 --lease-s "$lease_s" --secret "$work/secret" --log-dir "$work/$h" \
    > "$work/$h.log" 2>&1 &
  echo $! > "$work/$h.pid"
}
# The learner and the one-host league start before the cells: the tournament's 1-s games end in
# well under a minute once the cells run, so everything slow (Python's imports, a second league)
# comes first and the probe for fault 1 starts as the cells do.
# The learner's host: a trainer's vector env (one tennis match) on cell1 through olympics-relay,
# stepping all along; it must keep stepping while cell2 dies and cell3 is cut off. It waits up to
# 120 s for cell1's server, which starts with cell1 below.
pypath=$(cd "$bin/../python" 2>/dev/null && pwd || true)
learner=no
if [ -n "$pypath" ] && PYTHONPATH=$pypath $python -c "import smpl_olympics._client" 2>/dev/null; then
  learner=yes
  in_ns cell1 "$bin/olympics-relay" listen --port 7700 --secret "$work/secret" \
    > "$work/relay-cell1.log" 2>&1 &
  sleep 0.5
  in_ns learner "$bin/olympics-relay" connect --to "$net.11:7700" --secret "$work/secret" \
    > "$work/relay-learner.log" 2>&1 &
  in_ns learner env PYTHONPATH="$pypath" $python - "$work/learner-steps" "$work/secret" \
    > "$work/learner.log" 2>&1 <<'EOF2' &
import sys
import numpy as np
from smpl_olympics.vector_env import OlympicsVectorEnv
out, secret = sys.argv[1], sys.argv[2]
env = OlympicsVectorEnv(1, sport="tennis", mode="1v1", seed=7, time_limit_s=600,
                        secret_file=secret, server_id="cell1", connect_timeout_s=120,
                        lcm_url="udpm://239.255.76.67:7667?ttl=0")  # the relay's side
env.reset()
actions = np.zeros(env.action_space.shape, np.float32)
steps = 0
while True:
    env.step(actions)
    steps += 1
    if steps % 10 == 0:
        open(out + ".new", "w").write(str(steps))
        __import__("os").replace(out + ".new", out)
EOF2
fi
learner_steps() { cat "$work/learner-steps" 2>/dev/null || echo 0; }
# (Not waited for: the faults come while the tournament is young; the learner must be stepping
# by the end of cell3's cut, whenever it started.)
# The same tournament on one host, from SQLite, at the same time.
in_ns solo "$bin/olympics-server" serve --id solo --results "$work/solo-results.db" \
  --secret "$work/secret" \
  > "$work/solo-server.log" 2>&1 &
in_ns solo "$bin/olympics-league" run --db "$work/one.db" --name one --entrants "$list" --seed 5 \
  --time-limit "$time_limit" --parallel 2 --secret "$work/secret" --log-dir "$work" --quiet \
  > "$work/one.log" 2>&1 &
solo_league=$!

started=$(date +%s)
start_cell cell1 --server-capacity 3  # room for the learner's match beside the league's two
start_cell cell2
start_cell cell3

holds_game() {  # the cell has stored a game and holds one now
  [ "$(sql "SELECT count(*) FROM fleet_results WHERE tournament = '$name' AND cell = '$1'")" -ge 1 ] &&
    [ "$(sql "SELECT count(*) FROM fleet_queue WHERE tournament = '$name' AND cell = '$1' AND state = 'leased'")" -ge 1 ]
}

# Fault 1: cell2's host dies mid-match (its policy workers playing a game it holds).
agents_in() {  # policy workers running in the host's namespace (read from /proc: quick)
  local n=0 pid
  for pid in $(ip netns pids "$(ns "$1")"); do
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = olympics-agent ] && n=$((n + 1))
  done
  echo $n
}
playing() {  # workers running now, and a game leased: checked in that order, the cheap one first
  [ "$(agents_in "$1")" -ge 1 ] &&
    [ "$(sql "SELECT count(*) FROM fleet_queue WHERE tournament = '$name' AND cell = '$1' AND state = 'leased'")" -ge 1 ]
}
signal_host() {  # signal_host HOST SIGNAL: every process in the host's namespace
  local pid
  for pid in $(ip netns pids "$(ns "$1")"); do kill -"$2" "$pid" 2>/dev/null || true; done
}
caught_playing() {  # the host frozen (SIGSTOP) and found playing: left frozen; else thawed again
  # One-second games leave workers alive for moments: unfrozen, "workers running" and "a game
  # leased" were read at different instants and, under load, never once both held (the cell
  # played its whole share unseen). Frozen, both are read of one instant.
  signal_host "$1" STOP
  playing "$1" && return 0
  signal_host "$1" CONT
  return 1
}
wait_for "cell2 to be playing a game" 120 caught_playing cell2
signal_host cell2 KILL
# What it held when it died (a result it stored an instant before is not among them).
held=$(sql "SELECT string_agg(idx::text, ',') FROM fleet_queue WHERE tournament = '$name' AND cell = 'cell2' AND state = 'leased'")
[ -n "$held" ] || fail "cell2 held no game when it was killed"
echo "killed cell2 holding games $held"

# Fault 2: cell3's link goes down for cut_s seconds while it holds a game.
wait_for "cell3 to hold a game" 120 holds_game cell3
ip link set "$(cat "$work/cell3.link")" down
echo "cut cell3 off for ${cut_s}s"
steps_at_cut=$(learner_steps)
sleep "$cut_s"
steps_after_cut=$(learner_steps)
ip link set "$(cat "$work/cell3.link")" up
back_at=$(sql "SELECT now()")

for h in cell1 cell3; do
  left=$((deadline_s - ($(date +%s) - started)))
  for _ in $(seq $((left > 0 ? left * 5 : 1))); do
    kill -0 "$(cat "$work/$h.pid")" 2>/dev/null || break
    sleep 0.2
  done
  kill -0 "$(cat "$work/$h.pid")" 2>/dev/null && fail "$h still running after ${deadline_s}s"
  wait "$(cat "$work/$h.pid")" || fail "$h exited with $?: $(tail -5 "$work/$h.log")"
done
fleet_s=$(($(date +%s) - started))
wait $solo_league || fail "the one-host league failed: $(tail -5 "$work/one.log")"

# Every fixture stored exactly once, and every game done.
stored=$(sql "SELECT count(*) || ' ' || count(DISTINCT idx) FROM fleet_results WHERE tournament = '$name'")
[ "$stored" = "$games $games" ] || fail "results stored (rows, distinct games): $stored, expected $games"
done_games=$(sql "SELECT count(*) FROM games WHERE tournament = '$name' AND status = 2")
[ "$done_games" = "$games" ] || fail "$done_games of $games games done"
for idx in ${held//,/ }; do
  by=$(sql "SELECT cell FROM fleet_results WHERE tournament = '$name' AND idx = $idx")
  [ "$by" != cell2 ] || fail "game $idx was stored by the killed cell2"
done
replayed=$(sql "SELECT count(*) FROM fleet_queue WHERE tournament = '$name' AND leases > 1")
# The cut-off cell paused, came back and stored results after it.
grep -q "lost the database" "$work/cell3.log" || fail "cell3 never noticed the cut: $(tail "$work/cell3.log")"
grep -q "database back" "$work/cell3.log" || fail "cell3 never came back: $(tail "$work/cell3.log")"
# What it finished meanwhile reached the queue once it was back: stored, or (when its lease had
# run out and another cell played the game too) found stored already.
after=$(sql "SELECT count(*) FROM fleet_results WHERE tournament = '$name' AND cell = 'cell3' AND stored_at > '$back_at'")
twice3=$(grep -c "was stored already" "$work/cell3.log" || true)
[ $((after + twice3)) -ge 1 ] || fail "cell3 handed in nothing after its link came back"
# The same table as on one host (JSON: points, W/D/L, mu and sigma to the last digit).
"$bin/olympics-league" table --db "$db" --name "$name" --json > "$work/fleet-table.json"
in_ns solo "$bin/olympics-league" table --db "$work/one.db" --name one --json > "$work/one-table.json"
cmp -s "$work/fleet-table.json" "$work/one-table.json" ||
  fail "tables differ: $(diff "$work/one-table.json" "$work/fleet-table.json" | head -20)"
# The learner kept stepping on cell1 through the faults.
learner_note="no learner (the Python package is not built)"
if [ $learner = yes ]; then
  [ "$steps_after_cut" -gt "$steps_at_cut" ] ||
    fail "the learner did not step while cell3 was cut off ($steps_at_cut -> $steps_after_cut): $(tail -3 "$work/learner.log")"
  learner_note="the learner's vector env stepped on cell1 through the relay all along ($steps_at_cut -> $steps_after_cut steps during the cut, $(learner_steps) in all)"
fi
# No LCM datagram left any cell: the listener heard only the control.
kill -TERM $listener
sleep 0.3
[ "$(cat "$work/heard")" = 1 ] || fail "$(($(cat "$work/heard") - 1)) LCM datagram(s) left a cell"

twice=$(cat "$work"/cell*.log | grep -c "was stored already" || true)
per_cell=$(sql "SELECT string_agg(cell || ' ' || n, ', ') FROM (SELECT cell, count(*) n FROM fleet_results WHERE tournament = '$name' GROUP BY cell ORDER BY cell) c")
echo "PASSED: $games games over 3 cells in ${fleet_s}s ($per_cell); cell2 killed holding game(s) $held, $replayed fixture(s) leased again, $twice result(s) arrived twice and were stored once; cell3 cut off ${cut_s}s, paused and went on ($after stored after it, $twice3 found stored already); every game stored once; the table of one host; no LCM datagram left a cell; $learner_note"
