#!/usr/bin/env bash
# The README's main command: installs what is missing (Debian packages), builds, and runs
# the paired demo case cases/demo.prm (every engine it names, then the comparison report).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
scripts/build.sh
build/compare/cli/geocomp pair cases/demo.prm "$@"
echo "results: $(pwd)/results/demo (one HDF5 file per engine, docs/results-format.md)"
echo "report:  $(pwd)/results/demo/report/index.html"
