#!/usr/bin/env bash
# The README's main command: installs what is missing (Debian packages), builds, and runs
# the paired demo cases/demo_calibrated.prm: the DEM runs (the demo's isochoric shear and two
# lateral-pressure tests), the continuum calibrated on the latter and predicting the former,
# then the comparison report. `geocomp pair cases/demo.prm` pairs with the hand-set section.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
scripts/build.sh
build/compare/cli/geocomp pair cases/demo_calibrated.prm "$@"
echo "results: $(pwd)/results/demo (one HDF5 file per engine, docs/results-format.md)"
echo "report:  $(pwd)/results/demo/report/index.html"
