#!/bin/bash
# geocomp's side of the shared DEM benchmark (../shared/bench/README.md): for each N and
# 1 and 2 threads, prints lines ending "ns/particle-step: X".
# Usage: bench/run-dem-bench.sh [BENCH_BINARY] [DATA_DIR] [N ...]
#   defaults: build/bench/geocomp-dem-bench, ../shared/bench/data, 10000 50000
# The 100 000-sphere scaling point (not in the shared data), made like the shared packings:
#   build/bench/geocomp-bench-packing 100000 0.636 7 /tmp/bench_100000.xyzr 2
#   bench/run-dem-bench.sh build/bench/geocomp-dem-bench /tmp 100000
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../build/bench/geocomp-dem-bench}
data=${2:-$here/../../shared/bench/data}
shift $(( $# > 2 ? 2 : $# ))
NEQ=${NEQ:-500}; NT=${NT:-2000}
for N in ${@:-10000 50000}; do
  for t in 1 2; do
    OMP_NUM_THREADS=$t "$bin" "$data/bench_$N.xyzr" $t $NEQ $NT
  done
done
