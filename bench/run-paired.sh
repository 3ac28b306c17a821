#!/bin/bash
# The DEM benchmark paired with its peer, round by round: each round runs LIGGGHTS 3.8 at 1
# and 2 MPI processes (bench/run-liggghts-xyzr.sh, the shared deck) and geocomp at 1 and 2
# threads (geocomp-dem-bench) on the same packing, back to back, so both engines meet the
# same state of the machine (this virtual machine's speed moves 10-25 % within the hour:
# ratios are only meaningful between runs taken together). Prints every run, then per
# packing a markdown row: the fastest run of each column over the rounds, the ratios
# geocomp / LIGGGHTS at 1 and 2, geocomp's 2-thread speed-up, and the 1-thread ratio of
# each round (which pairs a geocomp run with the LIGGGHTS run next to it).
# Usage: bench/run-paired.sh [ROUNDS] [PACKING.xyzr ...]
#   defaults: 3 rounds on ../shared/bench/data/bench_10000.xyzr and bench_50000.xyzr
#   BENCH=path/to/geocomp-dem-bench (default build/bench/geocomp-dem-bench); NEQ, NT as
#   for the two runners (500 untimed + 2000 timed steps).
set -eu -o pipefail
here=$(cd "$(dirname "$0")" && pwd)
bench=${BENCH:-$here/../build/bench/geocomp-dem-bench}
rounds=${1:-3}
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "run-paired: ROUNDS: expected a positive integer, got '$rounds'" >&2; exit 2; }
shift $(( $# > 0 ? 1 : 0 ))
packings=("$@")
[ ${#packings[@]} -gt 0 ] || packings=("$here/../../shared/bench/data/bench_10000.xyzr" "$here/../../shared/bench/data/bench_50000.xyzr")
for p in "${packings[@]}"; do
  [ -r "$p" ] || { echo "run-paired: cannot read packing file '$p'" >&2; exit 2; }
done
[ -x "$bench" ] || { echo "run-paired: no geocomp-dem-bench at '$bench' (build first: scripts/build.sh, or set BENCH)" >&2; exit 2; }
export NEQ=${NEQ:-500} NT=${NT:-2000}

ns() { grep -o 'ns/particle-step: [0-9.]*' | awk '{print $2}' || true; }
need() { [ -n "$1" ] || { echo "run-paired: $2 printed no ns/particle-step line on '$p'" >&2; exit 1; }; }
table=$(mktemp); trap 'rm -f "$table"' EXIT
for p in "${packings[@]}"; do
  for r in $(seq "$rounds"); do
    peer=$("$here/run-liggghts-xyzr.sh" "$p")
    echo "$peer"
    l1=$(echo "$peer" | grep 'processes=1' | ns || true); l2=$(echo "$peer" | grep 'processes=2' | ns || true)
    need "$l1" "LIGGGHTS (1 process)"; need "$l2" "LIGGGHTS (2 processes)"
    g=()
    for t in 1 2; do
      line=$(OMP_NUM_THREADS=$t "$bench" "$p" $t "$NEQ" "$NT" | tail -1)
      echo "$line"
      g+=("$(echo "$line" | ns)")
      need "${g[-1]}" "geocomp-dem-bench (OMP_NUM_THREADS=$t)"
    done
    echo "$(basename "$p") $l1 ${g[0]} $l2 ${g[1]}" >> "$table"
  done
done

echo
echo "| packing | LIGGGHTS 1 proc | geocomp 1 thread | ratio | LIGGGHTS 2 procs | geocomp 2 threads | ratio | geocomp 2t/1t | 1-thread ratio per round |"
echo "|---|---|---|---|---|---|---|---|---|"
awk '
  function min(a, b) { return a < b ? a : b }
  !($1 in n) { order[++k] = $1; l1[$1] = $2; g1[$1] = $3; l2[$1] = $4; g2[$1] = $5 }
  {
    n[$1]++
    l1[$1] = min(l1[$1], $2); g1[$1] = min(g1[$1], $3); l2[$1] = min(l2[$1], $4); g2[$1] = min(g2[$1], $5)
    per[$1] = per[$1] (n[$1] > 1 ? ", " : "") sprintf("%.3f", $3 / $2)
  }
  END {
    for (i = 1; i <= k; ++i) {
      f = order[i]
      printf "| %s | %.1f | %.1f | %.3f | %.1f | %.1f | %.3f | %.2f | %s |\n", f, l1[f], g1[f], g1[f] / l1[f],
             l2[f], g2[f], g2[f] / l2[f], g1[f] / g2[f], per[f]
    }
  }' "$table"
echo "(ns per particle-step, fastest of $rounds round(s) per column)"
