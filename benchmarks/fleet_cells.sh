#!/usr/bin/env bash
# Matches per core with 1, 2 and 3 cells on this machine (docs/deploy.md, "How to size it"):
# the same tournament (8 bots, 28 games of 10 s tennis 1v1) queued once per cell count, and played
# by that many cells (each `olympics-league cell --spawn-server --parallel 1` on its own LCM port),
# the counts interleaved over --rounds. The CPU time of every cell, server and policy worker is
# read from a cpuacct cgroup (root, cgroup v1), so the figure is core-seconds per match whatever
# else the machine runs; wall time is printed beside it.
#
#   benchmarks/fleet_cells.sh BIN_DIR postgresql://... [ROUNDS]
set -euo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR DB_URL [ROUNDS]}" && pwd)
db=${2:?a postgresql:// URL}
rounds=${3:-1}
sport=${FLEET_SPORT:-tennis} time_limit=${FLEET_TIME_LIMIT:-10}
entrants=zero,random:1,random:2,random:3,random:4,random:5,random:6,random:7
root=/sys/fs/cgroup/cpuacct
[ -w "$root" ] || { echo "needs root and a cgroup v1 cpuacct hierarchy at $root"; exit 2; }
work=$(mktemp -d /tmp/fleet-cells-XXXXXX)
printf "%-6s %-6s %6s %8s %8s %12s %14s\n" cells round games wall_s cpu_s cpu_s/match matches/cpu_s
for round in $(seq "$rounds"); do
  for cells in 1 2 3; do
    name=cells${cells}_r${round}_$$
    "$bin/olympics-league" run --fleet --db "$db" --name "$name" --entrants "$entrants" \
      --seed 1 --sport "$sport" --time-limit "$time_limit" > /dev/null
    group=$root/fleet_cells_$$_$cells
    mkdir "$group"
    start=$(date +%s.%N)
    pids=()
    for c in $(seq "$cells"); do
      bash -c "echo \$\$ > $group/tasks; exec $bin/olympics-league cell --db '$db' --name $name \
        --cell c$c --spawn-server --parallel 1 --log-dir $work \
        --lcm-url 'udpm://239.255.76.67:$((7810 + c))?ttl=0'" > "$work/$name-c$c.log" 2>&1 &
      pids+=($!)
    done
    for pid in "${pids[@]}"; do wait "$pid"; done
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    cpu=$(echo "scale=3; $(cat "$group/cpuacct.usage") / 1000000000" | bc)
    for pid in $(cat "$group/tasks"); do kill -9 "$pid" 2>/dev/null || true; done
    sleep 0.5
    rmdir "$group"
    games=$(psql -qAt "$db" -c "SELECT count(*) FROM games WHERE tournament = '$name' AND status = 2")
    printf "%-6s %-6s %6s %8.1f %8.2f %12.3f %14.2f\n" "$cells" "$round" "$games" "$wall" "$cpu" \
      "$(echo "scale=4; $cpu / $games" | bc)" "$(echo "scale=4; $games / $cpu" | bc)"
  done
done
rm -rf "$work"
