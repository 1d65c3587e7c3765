#!/bin/bash
# olympics-bench racket's 1v1 and 2v2 breakdowns add up: every point is counted once in
# point_endings and once in the strokes histogram (and in point_endings_by_strokes under its
# strokes, which adds up to that histogram's count); each serve row's calls (1v1 and 2v2) add up
# to its serves; and a --seeds list too short for the request is refused with what to do (exit
# 2), not aborted. Usage: racket_bench_test.sh BIN_DIR
set -euo pipefail
bench="$1/olympics-bench"
out=$(mktemp)
trap 'rm -f "$out"' EXIT

"$bench" racket --sports table_tennis --episodes 1 --matches 1 --doubles 1 --serves 2 --seeds 1-3 \
  --no-speed --json >"$out"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
sport = json.load(open(sys.argv[1]))["sports"]["table_tennis"]
for mode in ("1v1", "2v2"):
    s = sport[mode]
    points = s["points"]
    assert points > 0, f"{mode}: no points played"
    endings = s["point_endings"]
    assert sum(endings.values()) == points, f"{mode}: point_endings {endings} != {points} points"
    histogram = s["strokes_per_point"]["histogram"]
    assert sum(histogram) == points, f"{mode}: histogram {histogram} != {points} points"
    assert len(histogram) == s["strokes_per_point"]["longest"] + 1, "histogram ends at the longest"
    by_strokes = s["point_endings_by_strokes"]
    for strokes, count in enumerate(histogram):
        ended = sum(by_strokes.get(str(strokes), {}).values())
        assert ended == count, f"{mode}: {ended} endings after {strokes} strokes != {count}"
    print(f"{mode}: {points} points: endings {endings}, histogram {histogram}")
for key, mode in (("serve", "1v1"), ("serve_2v2", "2v2")):
    serve = sport[key]
    assert serve["serves"] == 2 and serve["mode"] == mode, serve
    called = serve["in"]["count"] + serve["faults"] + serve["lets"] + serve["other"]
    assert called == 2, f"{key}: in, faults, lets and other {serve} do not add up to 2"
    assert sum(serve["fault_reasons"].values()) == serve["faults"], f"{key}: {serve}"
    print(f"{key}: {serve}")
PY

set +e
message=$("$bench" racket --sports table_tennis --balls 50 --matches 0 --seeds 1-2 --no-speed 2>&1)
status=$?
set -e
[ "$status" -eq 2 ] || { echo "too few seeds: exit $status, wanted 2: $message"; exit 1; }
grep -q -- "--seeds names 2 seeds, too few" <<<"$message" || { echo "unclear: $message"; exit 1; }
echo "too few seeds refused: $message"
