#!/bin/bash
# olympics-bench racket's 1v1 breakdown adds up: every point is counted once in point_endings
# and once in the strokes histogram; and a --seeds list too short for the request is refused
# with what to do (exit 2), not aborted. Usage: racket_bench_test.sh BIN_DIR
set -euo pipefail
bench="$1/olympics-bench"
out=$(mktemp)
trap 'rm -f "$out"' EXIT

"$bench" racket --sports table_tennis --episodes 1 --matches 1 --seeds 1-2 --no-speed --json >"$out"
python3 - "$out" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["sports"]["table_tennis"]["1v1"]
points = s["points"]
assert points > 0, "no points played"
endings = s["point_endings"]
assert sum(endings.values()) == points, f"point_endings {endings} do not add up to {points} points"
histogram = s["strokes_per_point"]["histogram"]
assert sum(histogram) == points, f"histogram {histogram} does not add up to {points} points"
assert len(histogram) == s["strokes_per_point"]["longest"] + 1, "histogram ends at the longest"
print(f"{points} points: endings {endings}, histogram {histogram}")
PY

set +e
message=$("$bench" racket --sports table_tennis --balls 50 --matches 0 --seeds 1-2 --no-speed 2>&1)
status=$?
set -e
[ "$status" -eq 2 ] || { echo "too few seeds: exit $status, wanted 2: $message"; exit 1; }
grep -q -- "--seeds names 2 seeds, too few" <<<"$message" || { echo "unclear: $message"; exit 1; }
echo "too few seeds refused: $message"
