#!/usr/bin/env bash
# Installs the dependencies, builds Peridot, runs the wave-in-a-bar example and plots its
# energies over time with peridot_post (python/; Debian's python3-netcdf4 and matplotlib).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" --target peridot peridot-diff
cd examples/wave_in_bar
../../build/peridot wave_in_bar.xml
PYTHONPATH=../../python /usr/bin/python3 -m peridot_post plot wave_in_bar.e \
  --globals Global_Kinetic_Energy Global_Stored_Elastic_Energy -o energies.png \
  --title "Wave in a bar: kinetic and stored elastic energy (J)"
echo "Wrote examples/wave_in_bar/wave_in_bar.e (open it in ParaView) and"
echo "examples/wave_in_bar/energies.png (the energies over time)."
