#!/usr/bin/env bash
# Installs grainflow's build and test dependencies from Debian packages.
# Runs apt-get only when something is missing (root, or sudo when available).
set -euo pipefail
pkgs=(build-essential cmake pkg-config git libyaml-dev libnetcdf-dev netcdf-bin libhdf5-dev
      libfftw3-dev libudunits2-dev libgsl-dev libsuitesparse-dev libopenmpi-dev openmpi-bin python3 python3-netcdf4 python3-xarray)
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
