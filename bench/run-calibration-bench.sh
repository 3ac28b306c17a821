#!/usr/bin/env bash
# Timed calibration (issue 8 benchmark): 5 continuum parameters (E, nu, c, phi at kappa =
# 0.02, psi at kappa = 0.02) from 3 DEM curves (constant lateral pressure 1, 2, 4 MPa,
# 3 000 spheres, particle friction 30 deg). Runs the three DEM cases first when their
# results are missing (about 1.5 min each), then times `geocomp calibrate` alone.
# Target: <= 30 s.
#
# Usage: bench/run-calibration-bench.sh [--verify]
#   GEOCOMP_BUILD_DIR  build folder holding compare/cli/geocomp (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${GEOCOMP_BUILD_DIR:-build}
exe=$build/compare/cli/geocomp
[ -x "$exe" ] || { echo "no $exe: build the geocomp target first (or set GEOCOMP_BUILD_DIR)" >&2; exit 1; }
for name in s0_lateral_pressure_phi30_n3000_1MPa s0_lateral_pressure_phi30_n3000 s0_lateral_pressure_phi30_n3000_4MPa; do
  if [ ! -f "results/small/$name/dem.h5" ]; then
    echo "running the DEM target cases/small/$name.prm"
    "$exe" dem "cases/small/$name.prm"
  fi
done
start=$(date +%s.%N)
"$exe" calibrate cases/calibration/s0_phi30_small.prm
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" 'BEGIN { printf "calibration wall time (5 parameters, 3 DEM curves): %.1f s (target <= 30 s)\n", b - a }'
if [ "${1:-}" = "--verify" ]; then
  start=$(date +%s.%N)
  "$exe" calibrate cases/calibration/s0_phi30_small.prm --verify
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "calibration + FE cube verification wall time: %.1f s\n", b - a }'
fi
