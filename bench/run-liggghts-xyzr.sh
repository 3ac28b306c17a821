#!/bin/bash
# The peer side of the DEM benchmark on any cubic packing in geocomp's xyzr format (e.g. the
# 100 000-sphere scaling point, which the shared data do not hold): writes the packing as a
# LIGGGHTS data file and its six box faces as STL meshes, laid out as ../shared/bench/data
# lays out the shared packings, then runs ../shared/bench/liggghts_bench.in on them (the same
# law, walls, skin and steps) at 1 and 2 MPI processes, printing ns per particle-step.
# Usage: bench/run-liggghts-xyzr.sh PACKING.xyzr
#   the packing's header: "# x y z r   box [0,L]x[0,L]x[0,L]" (geocomp-bench-packing writes it)
#   or "# x y z r   box [0,L]^3" (the shared packings)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
deck=$here/../../shared/bench/liggghts_bench.in
[ $# -eq 1 ] || { echo "usage: bench/run-liggghts-xyzr.sh PACKING.xyzr (one packing file)" >&2; exit 2; }
packing=$1
[ -r "$packing" ] || { echo "run-liggghts-xyzr: cannot read packing file '$packing'" >&2; exit 2; }
[ -r "$deck" ] || { echo "run-liggghts-xyzr: the shared LIGGGHTS deck '$deck' is missing" >&2; exit 2; }
L=$(head -1 "$packing" | sed -n -e 's/^# x y z r *box \[0,\([0-9.eE+-]*\)\]x\[0,\1\]x\[0,\1\]$/\1/p' \
                                -e 's/^# x y z r *box \[0,\([0-9.eE+-]*\)\]^3$/\1/p')
[ -n "$L" ] || { echo "run-liggghts-xyzr: '$packing' line 1: expected '# x y z r   box [0,L]x[0,L]x[0,L]' or '... box [0,L]^3' (a cube)" >&2; exit 2; }
N=$(awk 'NR > 1 && NF == 4' "$packing" | wc -l)
command -v liggghts >/dev/null || { echo "installing liggghts (Debian package)"; apt-get install -y -q liggghts >/dev/null; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir "$work/data"; cp "$deck" "$work/"
# Atoms: id type diameter density x y z (density 2650, as the shared specimens); the domain
# reaches 5 % of L beyond the walls, the meshes 2 %.
awk -v L="$L" -v N="$N" 'BEGIN {
    printf "geocomp packing N=%d L=%.9f\n\n%d atoms\n2 atom types\n\n", N, L, N
    for (a = 0; a < 3; ++a) printf "%.9f %.9f %s\n", -0.05 * L, 1.05 * L, substr("xlo xhiylo yhizlo zhi", 1 + 7 * a, 7)
    printf "\nAtoms\n\n"
  }
  NR > 1 && NF == 4 { printf "%d 1 %.9g 2650 %.17g %.17g %.17g\n", ++k, 2 * $4, $1, $2, $3 }' "$packing" > "$work/data/bench_$N.data"
awk -v L="$L" -v N="$N" -v dir="$work/data" 'BEGIN {
    lo = -0.02 * L; hi = 1.02 * L
    split("xlo xhi ylo yhi zlo zhi", name, " ")
    for (f = 1; f <= 6; ++f) {
      a = int((f - 1) / 2); at = (f % 2) ? 0 : L   # the face normal to axis a, at 0 or L
      file = dir "/wall_" name[f] "_" N ".stl"
      # two triangles over [lo,hi]^2 in the two other axes (b, c), as the shared meshes
      split("0 0|1 0|1 1|0 0|1 1|0 1", corner, "|")
      printf "solid wall\n" > file
      for (t = 0; t < 2; ++t) {
        printf "  facet normal %d %d %d\n    outer loop\n", a == 0, a == 1, a == 2 > file
        for (v = 1; v <= 3; ++v) {
          split(corner[3 * t + v], uv, " ")
          u = uv[1] ? hi : lo; w = uv[2] ? hi : lo
          if (a == 0) printf "      vertex %.9f %.9f %.9f\n", at, u, w > file
          if (a == 1) printf "      vertex %.9f %.9f %.9f\n", w, at, u > file
          if (a == 2) printf "      vertex %.9f %.9f %.9f\n", u, w, at > file
        }
        printf "    endloop\n  endfacet\n" > file
      }
      printf "endsolid wall\n" > file
      close(file)
    }
  }'
cd "$work"
NEQ=${NEQ:-500}; NT=${NT:-2000}
for np in 1 2; do
  mp=""; [ $np = 2 ] && mp="mpirun -np 2"
  OMP_NUM_THREADS=1 $mp liggghts -in liggghts_bench.in -var N $N -var NEQ $NEQ -var NT $NT -log log.$np >/dev/null 2>&1
  awk -v N=$N -v np=$np '/^Loop time of/ {s=$4; n=$9} END {printf "liggghts N=%d processes=%d steps=%d seconds=%.3f ns/particle-step: %.1f\n", N, np, n, s, s/n/N*1e9}' log.$np
done
