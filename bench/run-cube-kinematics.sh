#!/usr/bin/env bash
# The FE cube at finite against small strain on S0's isochoric program (lambda = 0, to
# gamma_max = 15 %; Mohr-Coulomb with the benchmark's softening cohesion and imperfection),
# back to back on the same machine, ROUNDS times each (issue 29 target: finite strain within
# 1.5x of the small-strain time, at most 6 Newton iterations per load step on average).
#
# Usage: bench/run-cube-kinematics.sh [N] [ROUNDS] [extra cube_benchmark key=value ...]
#   e.g. reuse=0 to rebuild ML's hierarchy for every solve (the default keeps it while it serves)
#   N       cells per edge (default 16); ROUNDS (default 1)
#   GEOCOMP_BUILD_DIR  build folder (default: build); the cube_benchmark target is built here.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-16}
rounds=${2:-1}
shift $(( $# > 2 ? 2 : $# ))
case "$n$rounds" in *[!0-9]*) echo "usage: $0 [N] [ROUNDS] [key=value ...]: N and ROUNDS are positive integers" >&2; exit 2;; esac
build=${GEOCOMP_BUILD_DIR:-build}
cmake --build "$build" --target cube_benchmark >/dev/null
exe=$build/continuum/fe/cube_benchmark
printf '| kinematics | round | steps | Newton its/step | GMRES its/solve | AMG builds | assembly s | solve s | total s | status |\n|---|---|---|---|---|---|---|---|---|---|\n'
for round in $(seq 1 "$rounds"); do
  for k in small finite; do
    # A run that stops mid-way (exit 1) still prints its statistics and '# FAILED: why'.
    out=$(OMP_NUM_THREADS=1 "$exe" n="$n" program=isochoric strain=0.15 samples=15 kinematics="$k" "$@") || true
    status=$(sed -n 's/^# FAILED: .*Newton did not converge at \(t = [0-9.]*\).*/failed at \1/p; s/^# FAILED: \(.*\)/failed: \1/p' <<<"$out" | head -1)
    steps=$(sed -n 's/^# steps \([0-9]*\) newton \([0-9]*\) (\([0-9.]*\)\/step).*(\([0-9.]*\)\/solve) preconditioner builds \([0-9]*\)$/\1 \3 \4 \5/p' <<<"$out")
    secs=$(sed -n 's/^# seconds: setup [0-9.]* assembly \([0-9.]*\) solve \([0-9.]*\) advance [0-9.]* total \([0-9.]*\)/\1 \2 \3/p' <<<"$out")
    [ -n "$steps" ] && [ -n "$secs" ] || { echo "cube_benchmark kinematics=$k printed no statistics:" >&2; echo "$out" | tail -5 >&2; exit 1; }
    read -r s its lin builds <<<"$steps"
    read -r asm sol tot <<<"$secs"
    printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$k" "$round" "$s" "$its" "$lin" "$builds" "$asm" "$sol" "$tot" \
      "${status:-complete}"
  done
done
