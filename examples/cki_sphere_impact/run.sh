#!/usr/bin/env bash
# V10 (paper 004 section 6), scaled: a CKI steel sphere at 50 m/s through a CKI brittle disc,
# short-range contact (make_impact.py's docstring says how it is scaled). Each run is
# "LAYERS:RATIO:RADIUS:GC:CHECKS" (make_impact.py --layers --ratio --radius --disc-gc; CHECKS a
# comma list of punch, hole, far, or -); analyse.py prints the sphere's history and the damage by
# radius, draws the figure and checks that the sphere went through (punch), that the hole is
# open (hole) and that nothing cracked beyond three sphere radii (far: the paper's result, which
# this model does not reproduce with the paper's parameters; README.md).
#   bash run.sh                                  # two runs of doc/verification.md (~2 min CPU each)
#   RUNS="2:2.015:0.04:1:punch,hole" DT=4e-7 bash run.sh   # the ctest example_v10_coarse
#   PERIDOT=/path/to/peridot WORK=/some/dir NP=2 bash run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PERIDOT="${PERIDOT:-$here/../../build/peridot}"
WORK="${WORK:-$here/out}"
RUNS="${RUNS:-4:2.015:0.06:1:punch,hole 4:2.015:0.06:1e4:-}"
FINAL="${FINAL:-8.6e-4}"
DT="${DT:-2e-7}"
NP="${NP:-1}"
PY=/usr/bin/python3
mkdir -p "$WORK"
cd "$WORK"
status=0
for run in $RUNS; do
  IFS=: read -r layers ratio radius gc checks <<< "$run"
  name="impact_l${layers}_m${ratio//./_}_r${radius//./_}_gc${gc//./_}"
  $PY "$here/make_impact.py" --layers "$layers" --ratio "$ratio" --radius "$radius" \
    --disc-gc "$gc" --final "$FINAL" --dt "$DT" --name "$name"
  start=$(date +%s.%N)
  if [ "$NP" -gt 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$NP" "$PERIDOT" "$name.yaml" > "$name.log"
  else
    "$PERIDOT" "$name.yaml" > "$name.log"
  fi
  echo "$name: wall $($PY -c "print(f'{$(date +%s.%N) - $start:.1f}')") s"
  args=("$name.e" --png "$name.png")
  for c in ${checks//,/ }; do
    case "$c" in
      punch) args+=(--check-punch) ;;
      hole) args+=(--check-hole) ;;
      far) args+=(--check-far-field) ;;
    esac
  done
  $PY "$here/analyse.py" "${args[@]}" || status=1
done
exit $status
