#!/usr/bin/env bash
# Builds Peridot (Release, -Wall -Wextra) and runs the whole test suite (ctest, not the
# `long` label). Usage: scripts/test.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
cd "$build"
ctest --output-on-failure -j "$(nproc)" -LE long
