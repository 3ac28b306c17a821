#!/usr/bin/env bash
# Builds S0's digital core store (26 specimens, cases/store/s0_*.prm) into cases/store/s0.h5.
# The 10 000-sphere variants take minutes each on 2 cores, the six 100 000-sphere ones
# longer (docs/specimens.md has the measured times). Already stored specimens are kept
# unless --force is given; names are the case files' `store name`.
# Usage: scripts/pack-s0-store.sh [--force] [case ...]   (default: all 26)
set -euo pipefail
cd "$(dirname "$0")/.."
force=0
[ "${1:-}" = "--force" ] && { force=1; shift; }
scripts/build.sh >/dev/null
geocomp=build/compare/cli/geocomp
store=cases/store/s0.h5
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=(cases/store/s0_n1000.prm cases/store/s0_n3000.prm cases/store/s0_n10000*.prm
                                 cases/store/s0_n30000.prm cases/store/s0_reference.prm cases/store/s0_phi*_2MPa.prm)
for c in "${cases[@]}"; do
  name=$(sed -n 's/^ *set store name *= *//p' "$c")
  if [ $force -eq 0 ] && [ -f $store ] && $geocomp export $store 2>/dev/null | grep -q "^$name:"; then
    echo "pack-s0-store: $name already in $store"
    continue
  fi
  start=$(date +%s)
  $geocomp pack "$c" | tail -2
  echo "pack-s0-store: $name in $(( $(date +%s) - start )) s"
done
$geocomp export $store
