#!/usr/bin/env bash
# V9 (paper 004 section 5): the CKI curved bar under a pressure pulse at both ends. Each run is
# "NN:P0:CHECK" (make_bar.py --nn NN --p0 P0, lattice cloud); analyse.py prints the crack
# initiation (time, place) and the stretch history; CHECK is
#   crack: the crack initiates inside the middle third of the bar, after the pulse front has
#          reached the far end and come back to the middle (1.5 S/c) and before the reflected
#          pulse has passed it (1.5 S/c + t1);
#   none:  no crack (damage > 0.5 away from the ends);
#   -:     no check.
#   bash run.sh                              # the runs of doc/verification.md (~5 min, 2 ranks)
#   RUNS="10:2.4e6:crack" FINAL=1e-3 bash run.sh   # the ctest example_v9_coarse
#   PERIDOT=/path/to/peridot WORK=/some/dir NP=2 bash run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PERIDOT="${PERIDOT:-$here/../../build/peridot}"
WORK="${WORK:-$here/out}"
RUNS="${RUNS:-20:4e5:none 20:2.4e6:crack}"
FINAL="${FINAL:-6e-3}"
NP="${NP:-2}"
PY=/usr/bin/python3
mkdir -p "$WORK"
cd "$WORK"
status=0
for run in $RUNS; do
  IFS=: read -r nn p0 check <<< "$run"
  name="curved_bar_n${nn}_p${p0//./_}"
  $PY "$here/make_bar.py" --nn "$nn" --p0 "$p0" --final "$FINAL" --output-dt 1e-5 --name "$name"
  start=$(date +%s.%N)
  if [ "$NP" -gt 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$NP" "$PERIDOT" "$name.yaml" > "$name.log"
  else
    "$PERIDOT" "$name.yaml" > "$name.log"
  fi
  echo "$name: wall $($PY -c "print(f'{$(date +%s.%N) - $start:.1f}')") s"
  args=("$name.e" --stretch)
  case "$check" in
    crack) args+=(--check-middle-third --check-after-reflection --check-during-reflected-pulse) ;;
    none) args+=(--check-no-crack) ;;
  esac
  $PY "$here/analyse.py" "${args[@]}" || status=1
done
exit $status
