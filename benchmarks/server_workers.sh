#!/usr/bin/env bash
# Server throughput at several worker counts (docs/server.md, "Several workers"): for each count W,
# `olympics-bench server` with a client thread per match (4W matches) and with one vector client
# (32W matches, async, each recv taking 16W). Meant for a machine with at least 16 cores; on fewer
# the workers share cores and the figure measures that instead. Prints one line per run and writes
# the JSON beside it.
#
#   benchmarks/server_workers.sh BIN_DIR OUT_DIR [WORKER_COUNTS...]   (default 1 4 8 16)
set -uo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR OUT_DIR [WORKER_COUNTS...]}" && pwd)
out=${2:?an output folder}
shift 2
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(1 4 8 16)
mkdir -p "$out"
figures='"ratio_server_over_bare"|"ratio_per_worker_cpu_second"|"served_ticks_per_s_per_worker"|round_trip_us_p(50|99)'
for w in "${counts[@]}"; do
  for clients in client-per-match vector; do
    args=(--seconds 5 --workers "$w" --json)
    if [ "$clients" = vector ]; then
      args+=(--matches $((32 * w)) --vector --async $((16 * w)))
    else
      args+=(--matches $((4 * w)))
    fi
    json="$out/$clients-w$w.json"
    timeout 300 "$bin/olympics-bench" server "${args[@]}" >"$json" 2>"$out/$clients-w$w.err"
    echo "workers=$w $clients rc=$? $(grep -E "$figures" "$json" | tr -d ' \n')"
  done
done
