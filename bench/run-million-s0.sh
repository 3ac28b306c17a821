#!/usr/bin/env bash
# Issue 36 item 3 on the many-core machine: the million-sphere S0 isochoric run
# (geocomp-bench-s0, docs/dem.md "Many cores") detached from the calling shell, so that one
# run can outlast the 10 minutes a single command may take there: `start` launches it in its
# own process session and waits, `wait` (a second command on the same machine) waits on.
# Each prints the log so far and copies it to $OUT when that is set.
# Usage: bench/run-million-s0.sh start BIN_DIR N THREADS GAMMA_MAX WAIT_S
#        bench/run-million-s0.sh wait WAIT_S
set -u
log_dir=/tmp/geocomp-s0-run
usage() { echo "usage: $0 start BIN_DIR N THREADS GAMMA_MAX WAIT_S | wait WAIT_S" >&2; exit 2; }

case "${1:-}" in
  start)
    [ $# -eq 6 ] || usage
    exe="$2/geocomp-bench-s0"
    [ -x "$exe" ] || { echo "$0: $exe is not an executable" >&2; exit 2; }
    mkdir -p "$log_dir"
    echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2), $(free -g | awk '/Mem:/ {print $2}') GiB"
    # The run's own session: it is not killed when this command returns. Its exit status
    # goes to the log's last line.
    setsid bash -c '"$1" "$2" "$3" "$4"; echo "exit status: $?"' run "$exe" "$3" "$4" "$5" \
      >"$log_dir/log" 2>&1 </dev/null &
    echo $! >"$log_dir/pid"
    wait_s=$6
    ;;
  wait)
    [ $# -eq 2 ] || usage
    [ -f "$log_dir/pid" ] || { echo "$0: no run started on this machine" >&2; exit 2; }
    wait_s=$2
    ;;
  *) usage ;;
esac

end=$((SECONDS + wait_s))
while [ $SECONDS -lt $end ] && ! grep -q '^exit status:' "$log_dir/log"; do
  sleep 2
done
grep -q '^exit status:' "$log_dir/log" || echo "still running after this command's ${wait_s} s"
[ -n "${OUT:-}" ] && cp "$log_dir/log" "$OUT/s0-run.log"
cat "$log_dir/log"
