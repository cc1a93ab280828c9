#!/bin/bash
# Starts `mpirun -np NP PERIDOT DECK` in the background, waits until WATCH exists (a periodic
# checkpoint or the output file: the run is under way), sends SIGTERM to the ranks themselves
# (the children of mpirun, as a batch system's pre-limit signal does), and exits with peridot's
# status. Output goes to LOG, errors to LOG.err (mpirun forwards the two streams apart, so in
# one file a rank's error line can be cut by its own later stdout).
# usage: signal_run.sh MPIEXEC NP PERIDOT DECK WATCH LOG
set -u
mpiexec=$1 np=$2 peridot=$3 deck=$4 watch=$5 log=$6
rm -f "$watch"
"$mpiexec" --oversubscribe -np "$np" "$peridot" "$deck" >"$log" 2>"$log.err" &
launcher=$!
for _ in $(seq 1 600); do
  [ -e "$watch" ] && break
  kill -0 "$launcher" 2>/dev/null || break
  sleep 0.05
done
ranks=$(pgrep -P "$launcher" -f "$peridot" || true)
if [ -z "$ranks" ]; then
  echo "signal_run.sh: no running rank to signal (the run ended too soon?)" >>"$log.err"
else
  kill -TERM $ranks
fi
wait "$launcher"
