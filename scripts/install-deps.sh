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
  # Python's headers and venv for the Python module (python/) when python3 is Debian's
  python3-dev python3-venv
  # ParaView 5.11 for the reader plugin (python/paraview/); its Python part below
  paraview
)

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
fi

# The Python module's build (nanobind, scikit-build-core) and tests (numpy, pytest, OpenEXR to
# read raytrace's images, Mitsuba 3 for its emitter plugin), from PyPI into a virtual environment
# in the build folder: pip installing into the system's Python would shadow Debian's python3-*
# packages (Debian 12 refuses it without --break-system-packages), and removing the build folder
# removes it with the rest.
# CMake builds the module for this environment's Python (-DPython_EXECUTABLE, scripts/test.sh).
venv="${RAYSET_VENV:-$(cd "$(dirname "$0")/.." && pwd)/build/venv}"
python_packages=("nanobind>=2.4" "scikit-build-core>=0.10" "numpy>=1.21" "pytest>=7" "OpenEXR>=3.2"
                 "mitsuba>=3.9,<4")
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
imports="import nanobind, scikit_build_core, numpy, pytest, OpenEXR, mitsuba"
if ! "$venv/bin/python" -c "$imports" 2> /dev/null; then
  echo "Installing into $venv: ${python_packages[*]}"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "${python_packages[@]}"
fi

# ParaView's Python (pvpython, and the GUI's Python plugins) is Debian's python3-paraview, which
# conflicts with python3-vtk9, a dependency of libvtk9-dev above: installing it would remove the
# VTK the build needs. It is unpacked into the build folder instead, beside a copy of the GUI:
# ParaView finds its Python modules relative to its executable, so build/paraview/usr/bin/pvpython
# and build/paraview/usr/bin/paraview run with ParaView's VTK, never python3-vtk9's.
paraview_root="${RAYSET_PARAVIEW:-$(cd "$(dirname "$0")/.." && pwd)/build/paraview}"
paraview_version=$(dpkg-query -W -f='${Version}' paraview)
if [ "$(cat "$paraview_root/version" 2> /dev/null)" != "$paraview_version" ]; then
  echo "Unpacking python3-paraview $paraview_version into $paraview_root"
  deb_dir=$(mktemp -d)
  # apt-get download runs as the user _apt where it can, which cannot write a private folder.
  chmod 755 "$deb_dir"
  download() { (cd "$deb_dir" && apt-get download -qq "python3-paraview=$paraview_version"); }
  download 2> /dev/null || { $sudo apt-get update -qq && download; }
  rm -rf "$paraview_root"
  dpkg-deb -x "$deb_dir"/python3-paraview_*.deb "$paraview_root"
  cp /usr/bin/paraview "$paraview_root/usr/bin/paraview"
  # ParaView 5.11.0's loader of Python plugins imports inspect.getargspec, which Python 3.11 no
  # longer has, so no Python plugin loads; getfullargspec is its replacement (same .args).
  sed -i 's/\bgetargspec\b/getfullargspec/g' \
    "$paraview_root/usr/lib/python3/dist-packages/paraview/detail/pythonalgorithm.py"
  echo "$paraview_version" > "$paraview_root/version"
  rm -rf "$deb_dir"
fi
