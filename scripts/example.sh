#!/usr/bin/env bash
# Installs the dependencies, builds Peridot and runs the wave-in-a-bar example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" --target peridot peridot-diff
cd examples/wave_in_bar
../../build/peridot wave_in_bar.xml
echo "Wrote examples/wave_in_bar/wave_in_bar.e (open it in ParaView)."
