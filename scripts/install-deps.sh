#!/usr/bin/env bash
# Installs geocomp's build and test dependencies from Debian's archive.
# Idempotent: when every package is already installed it prints nothing and takes
# well under a second. Used by both README commands (scripts/demo.sh, scripts/test.sh).
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libdeal.ii-dev libeigen3-dev libhdf5-openmpi-dev hdf5-tools openmpi-bin
  libgtest-dev libgmock-dev libbenchmark-dev libceres-dev nlohmann-json3-dev libcli11-dev libspdlog-dev
  gnuplot-nox clang libclang-rt-14-dev chromium
  python3-dev pybind11-dev python3-numpy python3-h5py python3-matplotlib
  liggghts
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
