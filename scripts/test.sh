#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian packages), builds, and runs
# every test: the GoogleTest suites through ctest, the same unit tests under ASan+UBSan,
# and a libFuzzer run over the case-file parser.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
start=$(date +%s)
stage() { echo "== $1 (at $(( $(date +%s) - start )) s)"; }
stage "build (Release)"
scripts/build.sh
stage ctest
# ctest runs nproc tests at once: one OpenMP thread each (case files default to all cores),
# so they do not oversubscribe; tests that need threads set them explicitly.
OMP_NUM_THREADS=1 ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
stage "sanitizers (ASan + UBSan) on the engine-independent unit tests"
scripts/sanitize.sh
stage "fuzzing the case-file parser (${GEOCOMP_FUZZ_SECONDS:-60} s)"
scripts/fuzz-case-parser.sh "${GEOCOMP_FUZZ_SECONDS:-60}"
echo "== all tests passed in $(( $(date +%s) - start )) s"
