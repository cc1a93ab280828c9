#!/usr/bin/env bash
# From a Gmsh geometry to plots: plate.geo -> plate.msh (gmsh) -> plate.e (peridot) -> PNGs and a
# CSV profile (python3 -m peridot_post). Runs in a few seconds.
#   bash run.sh                    # in this folder, with ../../build/peridot
#   PERIDOT=/path/to/peridot WORK=/some/dir bash run.sh
# Installed (cmake --install): peridot and peridot-post are taken from PATH.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ -z "${PERIDOT:-}" ]; then
  PERIDOT="$here/../../build/peridot"
  [ -x "$PERIDOT" ] || PERIDOT=peridot
fi
WORK="${WORK:-$here}"
if ! command -v gmsh > /dev/null; then
  echo "gmsh is not installed (apt-get install gmsh, or bash scripts/install-deps.sh): skipped"
  exit 77
fi
mkdir -p "$WORK"
[ "$WORK" -ef "$here" ] || cp "$here/plate.geo" "$here/plate.yaml" "$WORK/"
cd "$WORK"
gmsh -2 plate.geo -format msh41 -o plate.msh > gmsh.log
"$PERIDOT" plate.yaml
post() {
  if [ -d "$here/../../python/peridot_post" ]; then
    PYTHONPATH="$here/../../python${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 -m peridot_post "$@"
  else
    peridot-post "$@"
  fi
}
post info plate.e
post plot plate.e --globals Global_Kinetic_Energy Global_Stored_Elastic_Energy -o energies.png \
  --title "Plate with a hole: energies (J)"
post plot plate.e --globals Right_ReactionX -o reaction.png --title "Reaction on the right layer (N)"
post plot plate.e --globals Max_Damage -o damage.png --title "Largest damage"
post extract plate.e --field Displacement --line=-0.02,0.007,0:0.02,0.007,0 --points 41 \
  -o profile.csv
for f in energies.png reaction.png damage.png profile.csv; do
  [ -s "$f" ] || { echo "run.sh: $f was not written"; exit 1; }
done
echo "Wrote $WORK/energies.png, reaction.png, damage.png and profile.csv"
