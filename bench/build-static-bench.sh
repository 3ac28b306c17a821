#!/usr/bin/env bash
# Statically linked copies of the DEM benchmarks, for a machine that has none of the
# project's libraries (the many-core machine of issue 36: no deal.II, no HDF5, no OpenMP
# runtime): geocomp-dem-bench, geocomp-bench-ceiling and
# geocomp-bench-s0 (S0's isochoric program, docs/dem.md "Many cores"). It builds the three
# targets in the build folder (GEOCOMP_BUILD_DIR, default build/), links each object file
# with the libraries' .a files, `-static` and OpenMP (the whole of libpthread, which a static
# OpenMP needs), and checks that each copy starts here. geocomp-bench-s0 also needs
# the serial HDF5's static library and its dependencies (the specimen store is in the
# library; it writes nothing).
# Usage: GEOCOMP_BUILD_DIR=build bench/build-static-bench.sh OUT_DIR
set -euo pipefail
if [ $# -ne 1 ] || [ -z "$1" ]; then
  echo "usage: [GEOCOMP_BUILD_DIR=build] $0 OUT_DIR" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$root" && realpath -m "${GEOCOMP_BUILD_DIR:-build}")
if [ ! -f "$build/build.ninja" ] && [ ! -f "$build/Makefile" ]; then
  echo "$0: $build is not a configured build folder (set GEOCOMP_BUILD_DIR)" >&2
  exit 2
fi
mkdir -p "$1"
out=$(realpath "$1")
hdf5=/usr/lib/x86_64-linux-gnu/hdf5/serial

targets=(geocomp-dem-bench geocomp-bench-s0 geocomp-bench-ceiling)
nice -n 19 cmake --build "$build" -j1 --target "${targets[@]}"

openmp=(-fopenmp -Wl,--whole-archive -lpthread -Wl,--no-whole-archive)
dem=(dem/libgeocomp_dem.a dem/specimen/libgeocomp_dem_specimen.a common/libgeocomp_common.a)
cd "$build"
c++ -O3 -static bench/CMakeFiles/geocomp-dem-bench.dir/dem_bench.cpp.o "${dem[@]}" "${openmp[@]}" \
  -o "$out/geocomp-dem-bench"
c++ -O3 -static bench/CMakeFiles/geocomp-bench-s0.dir/s0_run.cpp.o dem/program/libgeocomp_dem_program.a \
  "${dem[@]}" "$hdf5/libhdf5.a" -lsz -laec -lz -ldl -lm "${openmp[@]}" -o "$out/geocomp-bench-s0"
c++ -O3 -static bench/CMakeFiles/geocomp-bench-ceiling.dir/thread_ceiling.cpp.o "${openmp[@]}" \
  -o "$out/geocomp-bench-ceiling"

# Each copy is static and starts (a bad argument: exit 2, nothing run).
for exe in "$out"/geocomp-dem-bench "$out"/geocomp-bench-s0 "$out"/geocomp-bench-ceiling; do
  if ldd "$exe" >/dev/null 2>&1; then
    echo "$0: $exe is not static" >&2
    exit 1
  fi
  echo "static: $exe"
done
set +e
"$out/geocomp-bench-s0" 2>/dev/null
[ $? -eq 2 ] || { echo "$0: $out/geocomp-bench-s0 does not start" >&2; exit 1; }
