#!/bin/bash
# olympics-bench's sport benches play the project's evaluation seeds (5001 on) when no seeds are
# named, never the low seeds the scripted players were tuned on (docs/figures.md); asking for
# none plays none. Usage: default_seeds_test.sh BIN_DIR
set -euo pipefail
bench="$1/olympics-bench"

seeds_of() {  # the JSON report's "seeds" and "match_seeds" (if any), tab-separated
  "$@" --no-speed --json | /usr/bin/python3 -c \
    'import json, sys; r = json.load(sys.stdin); print(r["seeds"], r.get("match_seeds", "-"), sep="\t")'
}
expect() {  # expect WANTED GOT WHAT
  [ "$1" = "$2" ] || { echo "$3: seeds \"$2\", wanted \"$1\""; exit 1; }
  echo "$3: $2"
}

expect "5001-5002	-" "$(seeds_of "$bench" combat --sports fencing --bouts 2 --pairings random_vs_random)" combat
expect "5001-5002	" "$(seeds_of "$bench" soccer --kicks 2 --policies zero --no-keeper --matches 0)" soccer
expect "5001-5002	-" "$(seeds_of "$bench" basketball --throws 2 --policies zero)" basketball
expect "5001-5002	-" "$(seeds_of "$bench" athletics --episodes 2 --events javelin --policies zero)" athletics
expect "9-10	-" "$(seeds_of "$bench" basketball --seeds 9-10 --policies zero)" "named seeds"
