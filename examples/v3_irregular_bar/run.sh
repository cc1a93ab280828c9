#!/usr/bin/env bash
# V3 (paper 000 Fig. 6): the wave bar from irregular tetrahedral meshes at several refinements.
# For each mesh size h: gmsh meshes bar.geo, the horizon is set so that a point has about 30
# neighbours on average (sphere volume = 30 x mean cell volume), peridot runs the pulse, and
# pulse.py measures the pulse position against c_l t and draws v3_pulse.png.
#   bash run.sh                                 # h = 1.6 1.3 1.0 0.8, 500 m bar, t = 80 s
#   H_LIST="1.6" LENGTH=250 FINAL=30 CHECK=0.10 bash run.sh   # the ctest's coarse check
#   NEIGHBOURS=60 H_LIST=1.6 bash run.sh      # more neighbours per point (default 30)
#   PERIDOT=/path/to/peridot WORK=/some/dir NP=2 bash run.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PERIDOT="${PERIDOT:-$here/../../build/peridot}"
WORK="${WORK:-$here/out}"
H_LIST="${H_LIST:-1.6 1.3 1.0 0.8}"
LENGTH="${LENGTH:-500}"
FINAL="${FINAL:-80}"
NP="${NP:-1}"
NEIGHBOURS="${NEIGHBOURS:-30}"
PY=/usr/bin/python3
if ! command -v gmsh > /dev/null; then
  echo "gmsh is not installed (apt-get install gmsh, or bash scripts/install-deps.sh): skipped"
  exit 77
fi
run() {
  if [ "$NP" -gt 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$NP" "$PERIDOT" "$@"
  else
    "$PERIDOT" "$@"
  fi
}
mkdir -p "$WORK"
cd "$WORK"
files=()
for h in $H_LIST; do
  name="v3_h${h/./p}"
  [ "$NEIGHBOURS" = 30 ] || name="${name}_n$NEIGHBOURS"
  gmsh -3 "$here/bar.geo" -setnumber h "$h" -setnumber L "$LENGTH" -format msh41 -o "$name.msh" > "$name.gmsh.log"
  n=$(sed -n '/^\$Elements/{n;p;q}' "$name.msh" | awk '{print $2}')
  seq 1 "$n" > all_points.txt
  horizon=$($PY -c "import math; print(f'{($NEIGHBOURS * $LENGTH * 16.0 / $n * 3 / (4 * math.pi)) ** (1 / 3):.6f}')")
  # Output about every 5 s of simulated time: the step comes from --check.
  sed -e "s/@MESH@/$name.msh/" -e "s/@HORIZON@/$horizon/" -e "s/@FINAL@/$FINAL/" \
    -e "s/@NAME@/$name/" -e "s/@FREQ@/1000000/" "$here/v3_bar.yaml.in" > "$name.yaml"
  dt=$("$PERIDOT" --check "$name.yaml" | sed -n 's/^Time step: \([0-9.e+-]*\).*/\1/p')
  freq=$($PY -c "print(max(1, round(5.0 / $dt)))")
  sed -i "s/Output Frequency: 1000000/Output Frequency: $freq/" "$name.yaml"
  echo "h = $h: $n tetrahedra, horizon $horizon m, dt $dt s"
  start=$(date +%s.%N)
  run "$name.yaml" > "$name.log"
  echo "  peridot: $(grep -m1 '^Points' "$name.log" || true); wall $($PY -c "print(f'{$(date +%s.%N) - $start:.1f}')") s"
  files+=("$name.e")
done
args=("${files[@]}" --png v3_pulse.png --csv v3_pulse.csv)
[ -n "${CHECK:-}" ] && args+=(--check-speed "$CHECK")
$PY "$here/pulse.py" "${args[@]}"
