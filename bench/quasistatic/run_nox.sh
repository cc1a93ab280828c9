#!/bin/sh
# NOXQuasiStatic against QuasiStatic: an LPS block NX x NY x NZ under tension, one load step, at
# 1 and 2 ranks: QuasiStatic (CG, no preconditioner), NOX Newton on the assembled tangent (CG,
# none), NOX Newton matrix-free (GMRES, none or 3x3 blocks), NOX NonlinearCG preconditioned by
# the 3x3 blocks (assembled J, or matrix-free J with the preconditioner kept 20 iterations).
# Prints the nonlinear and linear iterations and the load step's time. Usage:
# bench/quasistatic/run_nox.sh PERIDOT NX NY NZ (from any folder; writes in ./nox-bench).
set -e
peridot=$1; nx=$2; ny=$3; nz=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p nox-bench && cd nox-bench
for np in 1 2; do
  for case in "QuasiStatic None" "nox-newton None" "nox-newton-mf None" "nox-newton-mf Block 3x3" "nox-nlcg Block 3x3" "nox-nlcg-mf Block 3x3"; do
    solver=${case%% *}; pre=${case#* }
    /usr/bin/python3 "$here/make_deck.py" "$nx" "$ny" "$nz" "$pre" block.xml "$solver"
    echo "== $nx x $ny x $nz, $np rank(s), $solver, preconditioner $pre"
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      mpirun --oversubscribe -np "$np" "$peridot" block.xml 2>&1 |
      grep -E "^Points|Newton,|converged:|QuasiStatic: [0-9]|NOXQuasiStatic: [0-9]|  Tangent |  Linear solve|  Residual |  Preconditioner "
  done
done
