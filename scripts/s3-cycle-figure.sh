#!/usr/bin/env bash
# Makes docs/figures/s3-adhesion-cycle.png from the runs of cases/s3_adhesion_cycle.prm and
# cases/s3_bonded_cycle.prm (docs/s3-bonded.md, "Adhesion against cohesion after re-contact"):
# `geocomp dem cases/s3_<case>.prm` (or `pair`) for each first; their results folders may be
# given instead of results/s3_adhesion_cycle results/s3_bonded_cycle.
# Reads time, sigma_zz and eps_zz of each run's dem.h5 (h5dump) and plots them with gnuplot.
set -euo pipefail
cd "$(dirname "$0")/.."
adhesion=${1:-results/s3_adhesion_cycle}
bonded=${2:-results/s3_bonded_cycle}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
numbers() { # numbers <h5 file> <dataset>: its values, one a line
  h5dump -y -w 0 -d "$2" "$1" | awk '/DATA {/ {on = 1; next} on && /}/ {exit} on' | tr ',' '\n' | tr -d ' ' | grep -v '^$'
}
columns() { # columns <results dir>: time [ms], sigma_zz [kPa] (tension +), eps_zz [%]
  numbers "$1/dem.h5" /response/time > "$tmp/t"
  numbers "$1/dem.h5" /response/stress | awk 'NR % 9 == 0' > "$tmp/s"
  numbers "$1/dem.h5" /response/strain | awk 'NR % 9 == 0' > "$tmp/e"
  paste -d' ' "$tmp/t" "$tmp/s" "$tmp/e" | awk '{print 1e3 * $1, 1e-3 * $2, 100 * $3}'
}
# The first sample is taken in the step where every touching pair's adhesion forms at once
# (the platens' too): a jump of several hundred kPa, gone by the next sample; left out.
columns "$adhesion" | tail -n +2 > "$tmp/adhesion.dat"
columns "$bonded" | tail -n +2 > "$tmp/bonded.dat"
out=$PWD/docs/figures/s3-adhesion-cycle.png
cd "$tmp"
gnuplot <<GP
set terminal pngcairo size 900,720 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output '$out'
set multiplot layout 2,1
set grid lc rgb '#dddddd'
set key top right box opaque
set title 'S3 adhesion (eq. (7)) against cohesion (eq. (8)): tension, re-contact, tension (10 kPa lateral)'
set ylabel 'axial stress {/Symbol s}_{zz}, tension + [kPa]'
set yrange [-200:150]
plot 'adhesion.dat' using 1:2 with lines lc rgb '#2ca02c' title 'adhesion C_a = 1 MPa (restored at contact)', \
     'bonded.dat' using 1:2 with lines lc rgb '#d62728' title 'cohesion C_c = 1 MPa (breaks for good; bonds new contacts)', \
     0 with lines lc rgb '#888888' dt 2 notitle
unset title
set autoscale y
set xlabel 'time [ms]'
set ylabel 'axial strain {/Symbol e}_{zz} [%]'
plot 'adhesion.dat' using 1:3 with lines lc rgb '#555555' title 'the program (both runs)'
unset multiplot
GP
echo "wrote $out"
