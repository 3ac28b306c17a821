#!/usr/bin/env bash
# Fuzzes the case-file reader with libFuzzer (clang, ASan + UBSan), both syntaxes: the
# .prm reader (include expansion, line and size limits, UTF-8, deal.II's ParameterHandler)
# and the JSON reader (nlohmann-json's SAX parser, nesting limit, .prm conversion), half
# the time each, starting from the shipped cases and tests/bad_cases, with a dictionary of
# each syntax's tokens (tests/fuzz/*.dict). Exits non-zero on a crash, a stack overflow, a
# sanitizer report, a timeout (an input taking over 10 s) or an exception other than
# CaseError; the input that did it is kept as <build folder>/crash-* (or timeout-*).
#
# Usage: scripts/fuzz-case-parser.sh [seconds]
#   seconds   total time, shared by the two syntaxes; default 600 (the 10-minute run of
#             issue 31); scripts/test.sh (CI) runs it with 60.
# GEOCOMP_FUZZ_BUILD_DIR picks the build folder (default build-fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
build=${GEOCOMP_FUZZ_BUILD_DIR:-build-fuzz}
# Paths under the checkout hashed relative to it: another clone of the same sources hits the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" -DGEOCOMP_BUILD_TESTS=ON \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined" "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target case_prm_fuzzer case_json_fuzzer
half=$(( (seconds + 1) / 2 ))
for syntax in prm json; do
  corpus=$(mktemp -d)
  trap 'rm -rf "$corpus"' EXIT
  find cases tests/bad_cases -type f -name "*.$syntax" -exec cp -t "$corpus" {} + 2>/dev/null || true
  echo "-- case_${syntax}_fuzzer: $(ls "$corpus" | wc -l) seeds, ${half} s"
  ASAN_OPTIONS=detect_leaks=0 "$build/tests/fuzz/case_${syntax}_fuzzer" "$corpus" -dict="tests/fuzz/$syntax.dict" \
    -max_total_time="$half" -max_len=16384 -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$build/" 2>&1 | tail -5
  rm -rf "$corpus"
done
