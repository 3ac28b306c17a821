#!/usr/bin/env bash
# The RVE against the wall-bounded specimen of the same packing (issue 35; docs/coupled.md,
# "The RVE against the wall-bounded specimen"): every run of the comparison, one at a time on
# one thread, then the tables (<out>/summary.md) and the figure (docs/figures/rve-vs-specimen.png).
# The material is cases/fem-dem/biaxial_plane_strain.prm's; the program
# build/bench/geocomp-bench-rve-vs-specimen (bench/rve_vs_specimen.cpp; scripts/build.sh first).
#
# Usage: scripts/rve-vs-specimen.sh [output dir]      (default results/rve-vs-specimen)
# A run whose file exists is not run again (delete it, or the folder, to redo it); so an
# interrupted comparison continues where it stopped. About 22 min of one core in all.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/rve-vs-specimen}
bin=build/bench/geocomp-bench-rve-vs-specimen
case_file=cases/fem-dem/biaxial_plane_strain.prm
[ -x "$bin" ] || { echo "error: $bin not built (scripts/build.sh)" >&2; exit 2; }
export OMP_NUM_THREADS=1

# run <dir> <families> <particles> <seed> [rate [strain [shear damping]]]
run() {
  local dir=$1 families=$2 n=$3 seed=$4 missing=
  shift 4
  for f in ${families//,/ }; do
    [ -f "$dir/$f-n$n-s$seed.csv" ] || missing=1
  done
  [ -n "$missing" ] || return 0
  nice -n 19 "$bin" "$case_file" "$families" "$n" "$seed" "$dir" "$@"
}

# The two families (and the wall specimens' own particles as cells), at 1 /s to 10 %.
for seed in 1 2 3 4 5 6 7 8 9 10; do run "$out" rve 500 "$seed"; done
for seed in 1 2 3 4 5 6; do run "$out" wall,cell 5000 "$seed"; done
# Size: smaller wall specimens, larger RVEs.
for seed in 1 2 3 4 5; do run "$out" wall 1000 "$seed"; done
for seed in 1 2; do run "$out" rve 4000 "$seed"; done
# Checks: the rate (2 /s) and the damping while shearing (none), on three RVEs and one wall specimen.
for seed in 1 2 3; do run "$out/rate2" rve 500 "$seed" 2; done
run "$out/rate2" wall 5000 1 2
for seed in 1 2 3; do run "$out/damping0" rve 500 "$seed" 1 0.10 0; done
run "$out/damping0" wall 5000 1 1 0.10 0

/usr/bin/python3 scripts/rve-vs-specimen.py "$out"
figure=$PWD/docs/figures/rve-vs-specimen.png
cd "$out/plot"
gnuplot <<GP
set terminal pngcairo size 1400,560 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output '$figure'
set multiplot layout 1,2 title 'The RVE against the wall-bounded specimen: triaxial compression at p_0 = 100 kPa, 1 /s (bands: min-max of the seeds)'
set grid lc rgb '#dddddd'
set xlabel 'axial log strain {/Symbol e}_a [%] (compression +)'
set xrange [0:10]
set style fill transparent solid 0.18 noborder
set key bottom right box opaque
set ylabel 'q/p (p the current mean pressure)'
plot 'wall-n5000.dat' using 1:4:5 with filledcurves lc rgb '#d62728' notitle, \
     'rve-n500.dat' using 1:4:5 with filledcurves lc rgb '#1f77b4' notitle, \
     'wall-n5000.dat' using 1:2 with lines lw 2.5 lc rgb '#d62728' title 'wall box, 5 000 spheres (6 seeds)', \
     'rve-n500.dat' using 1:2 with lines lw 2.5 lc rgb '#1f77b4' title 'RVE, 500 spheres (10 seeds)', \
     'cell-n5000.dat' using 1:2 with lines lw 2 dt 2 lc rgb '#2ca02c' title 'the wall specimens as cells (6)', \
     'wall-n1000.dat' using 1:2 with lines lw 1.5 dt 3 lc rgb '#ff7f0e' title 'wall box, 1 000 spheres (5)', \
     'rve-n4000.dat' using 1:2 with lines lw 1.5 dt 4 lc rgb '#9467bd' title 'RVE, 4 000 spheres (2)'
set ylabel 'volumetric strain {/Symbol e}_v [%] (dilation +)'
set key top right box opaque
plot 'wall-n5000.dat' using 1:8:9 with filledcurves lc rgb '#d62728' notitle, \
     'rve-n500.dat' using 1:8:9 with filledcurves lc rgb '#1f77b4' notitle, \
     'wall-n5000.dat' using 1:6 with lines lw 2.5 lc rgb '#d62728' title 'wall box, 5 000', \
     'rve-n500.dat' using 1:6 with lines lw 2.5 lc rgb '#1f77b4' title 'RVE, 500', \
     'cell-n5000.dat' using 1:6 with lines lw 2 dt 2 lc rgb '#2ca02c' title 'cells of the wall specimens', \
     'wall-n1000.dat' using 1:6 with lines lw 1.5 dt 3 lc rgb '#ff7f0e' title 'wall box, 1 000', \
     'rve-n4000.dat' using 1:6 with lines lw 1.5 dt 4 lc rgb '#9467bd' title 'RVE, 4 000'
unset multiplot
GP
echo "$figure"
