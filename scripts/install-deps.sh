#!/usr/bin/env bash
# Installs Peridot's build and test dependencies from Debian 12 packages.
# Idempotent: packages already present are left alone. Needs root (or sudo).
set -euo pipefail
pkgs=(
  build-essential cmake pkg-config
  libtrilinos-teuchos-dev libtrilinos-tpetra-dev libtrilinos-epetra-dev
  libtrilinos-kokkos-dev libtrilinos-kokkos-kernels-dev libtrilinos-zoltan-dev
  libtrilinos-pamgen-dev libtrilinos-belos-dev libtrilinos-ifpack2-dev libtrilinos-nox-dev libptscotch-dev libscotch-dev
  libexodusii-dev libnetcdf-dev libopenmpi-dev openmpi-bin libboost-dev
  googletest libgtest-dev libbenchmark-dev netcdf-bin
  gmsh python3-netcdf4 python3-numpy python3-matplotlib
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#pkgs[@]} packages already installed"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
