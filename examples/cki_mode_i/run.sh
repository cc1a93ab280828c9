#!/usr/bin/env bash
# V8 (paper 004 section 4): the CKI mode-I square, 2D (cki_mode_i.yaml, 100 x 100 points) and 3D
# (cki_mode_i_3d.yaml, the paper's 60 x 60 x 3 points), each checked for one clean crack through
# (plot_damage.py --check). ~5 min (2D) and ~12 min CPU (3D); the ctest example_v8_long.
#   bash run.sh                      # both, in out/
#   DECKS=cki_mode_i.yaml PERIDOT=/path/to/peridot WORK=/some/dir NP=2 bash run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PERIDOT="${PERIDOT:-$here/../../build/peridot}"
WORK="${WORK:-$here/out}"
DECKS="${DECKS:-cki_mode_i.yaml cki_mode_i_3d.yaml}"
NP="${NP:-2}"
PY=/usr/bin/python3
mkdir -p "$WORK"
cd "$WORK"
$PY "$here/make_sets.py"
$PY "$here/make_sets.py" --3d
status=0
for deck in $DECKS; do
  cp "$here/$deck" .
  if [ "$NP" -gt 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$NP" "$PERIDOT" "$deck" > "${deck%.yaml}.log"
  else
    "$PERIDOT" "$deck" > "${deck%.yaml}.log"
  fi
  $PY "$here/plot_damage.py" "${deck%.yaml}.e" --check || status=1
done
exit $status
