#!/usr/bin/env bash
# Makes docs/figures/s3-bonded.png and docs/figures/s3-stick-slip.png from the runs of the
# S3 cases (docs/s3-bonded.md): `geocomp pair cases/s3_<case>.prm` for each first.
# Reads each run's report data (axial log strain, stress) and its broken-bond extra (h5dump).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
extra() { # extra <results dir> <name>: one value per sample
  h5dump -y -w 0 -d "/response/extras/$2" "$1/dem.h5" | sed -n '/DATA {/,/}/p' | grep -v 'DATA\|}' |
    tr ',' '\n' | tr -d ' ' | grep -v '^$' | grep -v '"'
}
for c in bonded_tension bonded_compression bonded_compression_cc2 stick_slip_kphi0 stick_slip_kphi1; do
  d=results/s3_$c
  grep -v '^#' "$d/report/data/r0_main.dat" > "$tmp/main.dat"
  extra "$d" broken_bonds | head -n "$(wc -l < "$tmp/main.dat")" | paste -d' ' "$tmp/main.dat" - > "$tmp/$c.dat"
done
cd "$tmp"
gnuplot <<GP
set terminal pngcairo size 1200,480 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output '$OLDPWD/docs/figures/s3-bonded.png'
set multiplot layout 1,2
set grid lc rgb '#dddddd'
set key top right box opaque
set title 'S3 bonded packing (1 000 spheres): axial stress'
set xlabel 'axial log strain |{/Symbol e}_z| [%]'
set ylabel 'axial stress in the loading sense [kPa]'
plot 'bonded_compression_cc2.dat' using 1:(\$2*1000) with lines lc rgb '#2ca02c' title 'compression, C_c = 2 MPa', \
     'bonded_compression.dat' using 1:(\$2*1000) with lines lc rgb '#1f77b4' title 'compression, C_c = 1 MPa', \
     'bonded_tension.dat' using 1:(\$2*1000) with lines lc rgb '#d62728' title 'tension, C_c = 1 MPa (platens bonded)'
set title 'Bonds broken for good (S3 eq. (8))'
set ylabel 'broken bonds'
set key top left box opaque
plot 'bonded_compression_cc2.dat' using 1:8 with lines lc rgb '#2ca02c' title 'compression, C_c = 2 MPa', \
     'bonded_compression.dat' using 1:8 with lines lc rgb '#1f77b4' title 'compression, C_c = 1 MPa', \
     'bonded_tension.dat' using 1:8 with lines lc rgb '#d62728' title 'tension, C_c = 1 MPa'
unset multiplot
set terminal pngcairo size 800,520 enhanced font 'DejaVu Sans,11' linewidth 1.5
set output '$OLDPWD/docs/figures/s3-stick-slip.png'
set title 'S3 friction (eq. (9)) in shear: unbonded packing, 10 kPa lateral'
set ylabel 'axial stress, compression + [kPa]'
set key bottom right box opaque
plot 'stick_slip_kphi0.dat' using 1:(\$2*1000) with lines lc rgb '#d62728' title 'k_{/Symbol f} = 0 (stick-slip)', \
     'stick_slip_kphi1.dat' using 1:(\$2*1000) with lines lc rgb '#1f77b4' title 'k_{/Symbol f} = 1 (Coulomb sliding)'
GP
