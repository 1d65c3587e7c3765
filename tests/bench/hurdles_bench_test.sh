#!/bin/bash
# olympics-bench athletics measures the hurdles under three rule sets: the seed's (paper), the
# official men's 110 m and the official women's 100 m (official_100m, 0.838 m hurdles), each
# over every seed asked, its endings adding up to the races; the scripted walker stops at the
# seed's first wall. Usage: hurdles_bench_test.sh BIN_DIR
set -euo pipefail
bench="$1/olympics-bench"
out=$(mktemp)
trap 'rm -f "$out"' EXIT

"$bench" athletics --events hurdles --policies zero,scripted --seeds 1-2 --no-speed --json >"$out"
python3 - "$out" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))["hurdles"]
assert sorted(h) == ["official", "official_100m", "paper"], f"rule sets {sorted(h)}"
for rules, policies in h.items():
    for policy, v in policies.items():
        assert v["races"] == 2, f"{rules} {policy}: {v['races']} races, wanted 2"
        assert sum(v["endings"].values()) == 2, f"{rules} {policy}: endings {v['endings']}"
assert h["paper"]["scripted"]["endings"] == {"touched_hurdle": 2}, h["paper"]["scripted"]
print({rules: {p: v["endings"] for p, v in policies.items()} for rules, policies in h.items()})
PY
