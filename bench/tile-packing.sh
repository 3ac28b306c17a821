#!/bin/bash
# Tiles a cubic `x y z r` packing of the shared benchmark (header "box [lo,hi]^3") twice
# along x, for the 100 000-sphere scaling point the shared data lack:
#   bench/tile-packing.sh ../shared/bench/data/bench_50000.xyzr > /tmp/bench_100000.xyzr
#   bench/run-dem-bench.sh build/bench/geocomp-dem-bench /tmp 100000
set -eu
awk 'NR == 1 {
       if (!match($0, /box \[[-+0-9.eE]+,[-+0-9.eE]+\]\^3/)) { print "tile-packing: " FILENAME ": expected a header with box [lo,hi]^3" > "/dev/stderr"; exit 2 }
       split(substr($0, RSTART + 5, RLENGTH - 7), b, ","); lo = b[1]; hi = b[2]; L = hi - lo; next }
     /^#/ || NF == 0 { next }
     { n++; x[n] = $1; y[n] = $2; z[n] = $3; r[n] = $4 }
     END {
       if (L == "") exit 2
       printf "# x y z r   box [%.17g,%.17g]x[%.17g,%.17g]x[%.17g,%.17g]  (tiled twice along x)\n", lo, lo + 2 * L, lo, hi, lo, hi
       for (t = 0; t < 2; t++) for (i = 1; i <= n; i++) printf "%.17g %s %s %s\n", x[i] + t * L, y[i], z[i], r[i]
     }' "$1"
