#!/usr/bin/env bash
# Fuzzes the case-file parser with libFuzzer (clang, ASan + UBSan) for N seconds
# (default 120), starting from the shipped cases and the bad cases. Exits non-zero on a
# crash, a sanitizer report or an exception other than CaseError.
# Usage: scripts/fuzz-case-parser.sh [seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-120}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" -DGEOCOMP_BUILD_TESTS=ON \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined" "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target case_parser_fuzzer
corpus=$(mktemp -d); trap 'rm -rf "$corpus"' EXIT
i=0
for f in cases/*.prm tests/bad_cases/*.prm; do
  [ -f "$f" ] || continue
  { printf '\0'; cat "$f"; } > "$corpus/seed$i"; i=$((i+1))
done
for f in cases/*.json tests/bad_cases/*.json; do
  [ -f "$f" ] || continue
  { printf '\1'; cat "$f"; } > "$corpus/seed$i"; i=$((i+1))
done
ASAN_OPTIONS=detect_leaks=0 build-fuzz/tests/fuzz/case_parser_fuzzer "$corpus" \
  -max_total_time="$seconds" -max_len=8192 -print_final_stats=1 -artifact_prefix=build-fuzz/ 2>&1 | tail -5
