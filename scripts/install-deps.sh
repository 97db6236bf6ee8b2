#!/usr/bin/env bash
# Installs what EDEM needs to build and test, from Debian's packages only; skips what is
# already installed. Run as root (or with sudo available). `--paraview` adds ParaView,
# `--slurm` Slurm and munge.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev liblua5.4-dev libhdf5-dev zlib1g-dev libsundials-dev libsuitesparse-dev
  libopenblas0-serial  # replaces reference BLAS under UMFPACK (prepass 1.6x faster); serial beside OpenMP
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libgtest-dev libbenchmark-dev libcairo2-dev libcli11-dev libfmt-dev
  python3-h5py  # tests read the field output back with it (an independent reader)
)

# --paraview: Debian's paraview as well, for the long test that opens the field output in it
# (ctest -L long -R output.paraview); large, so only on request.
# --slurm: Slurm's daemons and commands and munge, for the long test that runs edem sweep on a
# single-node cluster it starts (ctest -L long -R sweep.slurm).
for option in "$@"; do
  case $option in
    --paraview) packages+=(paraview python3-paraview) ;;
    --slurm) packages+=(slurm-wlm munge) ;;
    *) echo "install-deps: unknown option '$option' (--paraview, --slurm)" >&2; exit 2 ;;
  esac
done

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
