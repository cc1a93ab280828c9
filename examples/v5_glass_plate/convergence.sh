#!/usr/bin/env bash
# Paper 002's mesh-convergence study of the glass plate (section 4.3, Table 3, Figs. 9 and 11):
# DTT at 4 MPa, delta = 1 mm, m = delta/h from M_LIST; the largest m is the reference.
# convergence.py prints the displacement differences at the last record (Table 3), the energies
# and their differences from the reference (Figs. 9 and 11) and checks that E = Ep + Ek - W never
# rises (paper 002 Theorem 4); it draws v5_convergence.png.
#   bash convergence.sh                                   # m = 2, 3, 6, 12 to 20 us (NP=2: ~15 min)
#   M_LIST="2 3 4" FINAL=6 CHECK=1 bash convergence.sh    # the ctest example_v5_convergence_coarse
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
WORK="${WORK:-$here/out}"
M_LIST="${M_LIST:-2 3 6 12}"
export FINAL="${FINAL:-20}"
runs=()
files=()
for m in $M_LIST; do
  runs+=("dtt:4:$m")
  files+=("$WORK/v5_dtt_s4_m$m.e")
done
RUNS="${runs[*]}" CHECK="" WORK="$WORK" bash "$here/run.sh"
args=("${files[@]}" --plot "$WORK/v5_convergence.png")
[ -n "${CHECK:-}" ] && args+=(--check)
/usr/bin/python3 "$here/convergence.py" "${args[@]}"
