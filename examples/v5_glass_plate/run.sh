#!/usr/bin/env bash
# V5 (paper 001 section 3, paper 002 section 4.3): the soda-lime glass plate, a subset of the
# papers' runs at reduced resolution. Each run is "MODEL:SIGMA_MPA:M" (make_plate.py); analyse.py
# prints initiation, tip speed over c_R, branching time, branch point and angle, and draws the
# damage maps (v5_maps.png) and tip speeds (v5_speed.png).
#   bash run.sh                                          # the runs of doc/verification.md (~25 min)
#   RUNS="dtt:4:2" CHECK="0.4 0.9" bash run.sh           # the ctest example_v5_coarse
#   PERIDOT=/path/to/peridot WORK=/some/dir NP=2 bash run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PERIDOT="${PERIDOT:-$here/../../build/peridot}"
WORK="${WORK:-$here/out}"
RUNS="${RUNS:-pmb:4:3 dtt:4:3 lpst:4:3 lsjt:4:3 dtt:4:2 dtt:4:4 dtt:2:3 dtt:0.2:2}"
NP="${NP:-1}"
PY=/usr/bin/python3
mkdir -p "$WORK"
cd "$WORK"
files=()
for run in $RUNS; do
  IFS=: read -r model sigma m <<< "$run"
  deck=$($PY "$here/make_plate.py" "$model" "$sigma" "$m" ${FINAL:+--final "$FINAL"} | cut -d: -f1)
  start=$(date +%s.%N)
  if [ "$NP" -gt 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$NP" "$PERIDOT" "$deck" > "${deck%.yaml}.log"
  else
    "$PERIDOT" "$deck" > "${deck%.yaml}.log"
  fi
  echo "$deck: $(grep -m1 '^Points' "${deck%.yaml}.log"); wall $($PY -c "print(f'{$(date +%s.%N) - $start:.1f}')") s"
  files+=("${deck%.yaml}.e")
done
args=("${files[@]}" --maps v5_maps.png --speed v5_speed.png --csv v5.csv)
[ -n "${CHECK:-}" ] && args+=(--check-speed $CHECK)
$PY "$here/analyse.py" "${args[@]}"
