#!/bin/sh
# QuasiStatic bench: an LPS block NX x NY x NZ under tension, one load step, at 1 and 2 ranks with
# each preconditioner. Prints Newton and linear iterations, the load step's time and the tangent
# memory per bond. Usage: bench/quasistatic/run.sh PERIDOT NX NY NZ (from any folder; writes in
# ./quasistatic-bench).
set -e
peridot=$1; nx=$2; ny=$3; nz=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p quasistatic-bench && cd quasistatic-bench
for np in 1 2; do
  for pre in "None" "Block 3x3" "Full Tangent"; do
    /usr/bin/python3 "$here/make_deck.py" "$nx" "$ny" "$nz" "$pre" block.xml
    echo "== $nx x $ny x $nz, $np rank(s), preconditioner $pre"
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      mpirun --oversubscribe -np "$np" "$peridot" block.xml 2>&1 |
      grep -E "^Points|Newton,|QuasiStatic: [0-9]|Tangent memory|  Tangent |  Linear solve"
  done
done
