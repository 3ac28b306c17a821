#!/usr/bin/env bash
# Builds the unit-test executables that do not need deal.II with AddressSanitizer and
# UndefinedBehaviorSanitizer into build-asan/ and runs them.
# GEOCOMP_ASAN_BUILD_DIR picks the build folder (default build-asan).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${GEOCOMP_ASAN_BUILD_DIR:-build-asan}
# Paths under the checkout hashed relative to it: another clone of the same sources hits the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1: the sanitizers need no more, and it compiles much faster than Release's -O3.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" -DGEOCOMP_SANITIZE=ON "${launcher[@]}" >/dev/null
cmake --build "$build" --target help > "$build/targets.txt"
targets=()
for t in common_tests dem_tests dem_specimen_tests continuum_model_tests compare_tests; do
  grep -qE "(^|[ .:])$t(:|$)" "$build/targets.txt" && targets+=("$t")
done
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Two at a time (the machine's two cores): the longest, dem_tests, beside the others in turn.
# Each writes its own log, printed when it ends; any failure fails the script.
run_one() {
  local t=$1 exe
  exe=$(find "$PWD/$build" -type f -name "$t" -perm -u+x | head -1)
  GEOCOMP_SOURCE_DIR="$PWD" "$exe" --gtest_brief=1 > "$build/$t.log" 2>&1
}
say() { echo "-- $1 (sanitized): $2"; cat "$build/$1.log"; }
long=() rest=()
for t in "${targets[@]}"; do
  if [ "$t" = dem_tests ]; then long+=("$t"); else rest+=("$t"); fi
done
failed=0
if [ ${#long[@]} -gt 0 ]; then run_one "${long[0]}" & long_pid=$!; fi
for t in "${rest[@]}"; do
  if run_one "$t"; then say "$t" passed; else say "$t" FAILED; failed=1; fi
done
if [ ${#long[@]} -gt 0 ]; then
  if wait "$long_pid"; then say "${long[0]}" passed; else say "${long[0]}" FAILED; failed=1; fi
fi
exit "$failed"
