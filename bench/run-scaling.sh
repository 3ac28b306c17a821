#!/bin/bash
# DEM thread scaling on a many-core machine (issue 36; docs/dem.md, "Many cores"): the
# machine's ceiling (geocomp-bench-ceiling: triad bandwidth at 96 MB and 1 GB, register
# arithmetic), then the shared benchmark (geocomp-dem-bench, GEOCOMP_PROFILE=1: time per
# phase of the step and per part of the rebuild) on 10 000, 100 000 and 1 000 000 spheres at
# each thread count. The 1 000 000-sphere specimen is the 100 000-sphere packing tiled
# 5 x 2 x 1, the tiles 1.5 mm apart (its spheres reach 0.6 mm beyond its walls); the seams
# are free faces of a confined packing, so that specimen expands and rebuilds its lists
# every 20-50 steps: its figures include rebuilds, as a shearing specimen's would.
#
# Usage: bench/run-scaling.sh PACKING_100000.xyzr [THREADS ...]   (default threads 1 2 4 8 16)
#   the 100 000-sphere packing: geocomp-bench-packing 100000 0.636 7 bench_100000.xyzr
#   BENCH_DIR: where geocomp-dem-bench and geocomp-bench-ceiling are (default build/bench);
#   statically linked copies of both run on a machine without the project's libraries.
set -eu -o pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=${BENCH_DIR:-$here/../build/bench}
[ $# -ge 1 ] || { echo "usage: $0 PACKING_100000.xyzr [THREADS ...]" >&2; exit 2; }
p100k=$1
shift
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1 2 4 8 16)
for t in "${threads[@]}"; do
  [[ "$t" =~ ^[1-9][0-9]*$ ]] || { echo "run-scaling: THREADS: expected positive integers, got '$t'" >&2; exit 2; }
done
p10k=$here/../../shared/bench/data/bench_10000.xyzr
for p in "$p100k" "$p10k"; do [ -r "$p" ] || { echo "run-scaling: cannot read packing '$p'" >&2; exit 2; }; done
for b in geocomp-dem-bench geocomp-bench-ceiling; do
  [ -x "$bin/$b" ] || { echo "run-scaling: no $b in '$bin' (build first, or set BENCH_DIR)" >&2; exit 2; }
done
p1m=$(mktemp --suffix=.xyzr)
trap 'rm -f "$p1m"' EXIT
awk 'NR == 1 { match($0, /\[0,[0-9.eE+-]+\]/); L = substr($0, RSTART + 3, RLENGTH - 4) + 0; P = L + 0.0015;
       printf "# x y z r   box [0,%.17g]x[0,%.17g]x[0,%.17g]\n", 4 * P + L, P + L, L; next }
     /^#/ { next }
     { for (i = 0; i < 5; ++i) for (j = 0; j < 2; ++j) printf "%.17g %.17g %.17g %.17g\n", $1 + i * P, $2 + j * P, $3, $4 }' \
  "$p100k" > "$p1m"
max=0
for t in "${threads[@]}"; do (( t > max )) && max=$t; done
"$bin/geocomp-bench-ceiling" "$max"
run() { GEOCOMP_PROFILE=1 OMP_NUM_THREADS=$2 "$bin/geocomp-dem-bench" "$1" "$2" "$3" "$4"; }
for t in "${threads[@]}"; do run "$p10k" "$t" 300 3000; done
for t in "${threads[@]}"; do run "$p100k" "$t" 100 800; done
for t in "${threads[@]}"; do run "$p1m" "$t" 10 100; done
