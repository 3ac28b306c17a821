#!/usr/bin/env bash
# Timed calibration: 5 continuum parameters from 3 DEM curves (constant lateral pressure at
# 1, 2, 4 MPa, 3 000 spheres). Runs the three DEM cases first when their results are missing
# (a few minutes), then times `geocomp calibrate`. Usage: bench/run-calibration-bench.sh
set -euo pipefail
cd "$(dirname "$0")/.."
exe=build/compare/cli/geocomp
[ -x "$exe" ] || scripts/build.sh
for c in cases/small/s0_lateral_pressure_phi30_n3000_1MPa.prm cases/small/s0_lateral_pressure_phi30_n3000.prm \
         cases/small/s0_lateral_pressure_phi30_n3000_4MPa.prm; do
  "$exe" dem "$c"
done
start=$(date +%s.%N)
"$exe" calibrate cases/calibration/s0_phi30_small.prm
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" 'BEGIN { printf "calibration wall time: %.1f s\n", b - a }'
