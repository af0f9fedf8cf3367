#!/usr/bin/env bash
# Installs grainflow's build and test dependencies from Debian packages.
# Runs apt-get only when something is missing (root, or sudo when available).
set -euo pipefail
# One package a line, so that a new dependency is one added line.
pkgs=(
  build-essential cmake pkg-config git
  libyaml-dev libnetcdf-dev netcdf-bin libhdf5-dev libfftw3-dev libudunits2-dev
  libopenmpi-dev openmpi-bin
  zlib1g-dev       # CRC-32 of run manifests (postproc/rundir/gf_manifest.c)
  libxml2-dev      # the XDMF sidecar test (tests/io/test_nc_sidecar.c)
  libgsl-dev       # root finding and quadrature of the mu(I) oracles (engine/continuum)
  libsuitesparse-dev  # UMFPACK LU of the continuum solver's stress divergence
  python3 python3-netcdf4 python3-xarray
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "grainflow: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
