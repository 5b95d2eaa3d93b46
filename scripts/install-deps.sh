#!/usr/bin/env bash
# Installs the Debian 12 packages rayset builds and tests with, skipping those already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libopenvdb-dev libopenvdb-tools libboost-iostreams-dev libceres-dev libopenexr-dev libvtk9-dev
  libtbb-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libeigen3-dev libpng-dev libtinyobjloader-dev libfreetype-dev libopenimageio-dev xvfb xauth time
  # clang and its libFuzzer and sanitizer runtimes: the fuzz tree (scripts/fuzz.sh)
  clang libclang-rt-14-dev
  # Open MPI: raytrace across processes and machines (mpirun -n N raytrace ...)
  openmpi-bin libopenmpi-dev
  # POV-Ray 3.7: the reference renderer of the framing and differential tests, its include
  # folder (on raytrace's default include path) and its sample scenes (scripts/pov_compat.sh)
  povray povray-includes povray-examples
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
