#!/usr/bin/env bash
# The installed package works for another CMake project (issue 37 item 2): installs the
# build into a fresh prefix (`cmake --install`), configures and builds the consumer of
# tests/install/consumer against it alone (find_package(geocomp), a C++-only project), runs
# the `geocomp` command installed there on the demo case's material point, and runs the
# consumer, which must reproduce that curve bit for bit (and the DEM's momentum balance).
# Usage: tests/install/consumer-test.sh BUILD_DIR
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
for h in common/ProgramRunner.h common/Version.h dem/DemSystem.h compare/Metrics.h compare/cli/Engines.h; do
  [ -f "$work/prefix/include/geocomp/$h" ] || { echo "not installed: include/geocomp/$h" >&2; exit 1; }
done

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }

"$work/prefix/bin/geocomp" material-point "$source_dir/cases/demo.prm" --output "$work/cli" >"$work/cli.log" 2>&1 ||
  { cat "$work/cli.log"; exit 1; }
(cd "$work" && "$work/consumer/geocomp_consumer" "$source_dir/cases/demo.prm" "$work/cli/material-point.h5")

# The Python package installed beside them imports from there and reads the same results.
if [ -d "$build/python/geocomp" ]; then
  (cd "$work" && PYTHONPATH="$work/prefix/lib/python3/dist-packages" /usr/bin/python3 -c '
import sys, geocomp
assert geocomp.__file__.startswith(sys.argv[1]), geocomp.__file__
r = geocomp.read_results(sys.argv[2])
assert len(r) > 0 and r.status == "complete", r
print("ok: the installed Python package reads the CLI results (%d samples)" % len(r))
' "$work/prefix" "$work/cli/material-point.h5")
fi
