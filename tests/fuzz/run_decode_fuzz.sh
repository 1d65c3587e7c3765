#!/usr/bin/env bash
# Builds tests/fuzz/decode_fuzz.cpp with clang's libFuzzer, AddressSanitizer and UBSan, and fuzzes
# every decoder for SECONDS from a corpus of one valid message per type. Exit status 0: no crash.
#   run_decode_fuzz.sh SOURCE_DIR BUILD_DIR [SECONDS]
set -euo pipefail
src=$1 build=$2 seconds=${3:-30}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I"$src/protocol" -I"$src/lcmtypes" -I"$build/lcmtypes/cpp" $(pkg-config --cflags lcm) \
  "$src/tests/fuzz/decode_fuzz.cpp" "$src/protocol/wire_check.cpp" -o "$work/decode_fuzz"
mkdir -p "$work/corpus"
"$work/decode_fuzz" --write-seeds "$work/corpus"
"$work/decode_fuzz" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=1024 \
  -artifact_prefix="$work/" "$work/corpus" 2>&1 | tail -40
