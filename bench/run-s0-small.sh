#!/usr/bin/env bash
# S0's programs on the small specimens, timed, with the numbers issue 5 asks for:
# isochoric lambda = 0 on 5 000 spheres (peak, residual strains of the five branches,
# largest inertial number) and constant lateral pressure on 3 000 spheres for friction
# angles 0 ... 60 deg (peak, secant modulus, largest compaction). About 10 minutes on 2 cores.
# GEOCOMP_EXE=path runs another build of geocomp.
# Usage: bench/run-s0-small.sh [--force]
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${GEOCOMP_EXE:-build/compare/cli/geocomp}
[ -x "$exe" ] || scripts/build.sh
column() { # dataset of a results file, one value per line
  h5dump -y -w 0 -d "$2" "$1" | sed -n '/DATA {/,/}/p' | sed -n 2p | tr ',' '\n' | sed 's/ //g' | grep -v '^$'
}
json() { python3 -c "import json,sys; d=json.load(sys.stdin)['metrics']['DEM']; print($1)"; }

iso=cases/small/s0_isochoric_lambda0_n5000.prm
start=$(date +%s)
"$exe" dem "$iso" "$@"
echo "isochoric: $(( $(date +%s) - start )) s wall"
dir=results/small/s0_isochoric_lambda0_n5000
echo "  branches (trigger | gamma_start | residual gamma):"
paste <(h5dump -y -w 0 -d /branches/trigger "$dir/dem.h5" | sed -n '/DATA {/,/}/p' | sed -n 2p | tr ',' '\n' | sed 's/^ *//') \
      <(column "$dir/dem.h5" /branches/gamma_start) <(column "$dir/dem.h5" /branches/residual_gamma)
echo "  largest inertial number: $(column "$dir/dem.h5" /response/extras/inertial_number | sort -g | tail -1)"
"$exe" compare "$iso" 2>/dev/null | json "'  peak tau %.3f MPa at gamma %.2f %%; residual %s MPa' % (d['peak_stress_MPa'], d['peak_strain_pct'], d['residual_stress_MPa'])" || true

for phi in 0 15 30 45 60; do
  c=cases/small/s0_lateral_pressure_phi${phi}_n3000.prm
  start=$(date +%s)
  "$exe" dem "$c" "$@" > /dev/null
  d=results/small/s0_lateral_pressure_phi${phi}_n3000
  minv=$(column "$d/dem.h5" /response/volumetric_strain | sort -g | head -1)
  "$exe" compare "$c" 2>/dev/null | json "'phi_s = $phi deg: peak %.3f MPa at %.1f %%, secant modulus %.1f MPa, largest compaction eps_v = %.3f %%, $(( $(date +%s) - start )) s' % (d['peak_stress_MPa'], d['peak_strain_pct'], d['secant_modulus_MPa'], 100 * $minv)"
done
