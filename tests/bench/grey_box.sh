#!/usr/bin/env bash
# Convergence in a closed grey room lit by a ray-file source (grey_box/grey_box.pov), raytrace
# against Mitsuba 3 on the same machine in the same run: relative RMSE of each image against its
# own renderer's converged reference as the samples per pixel double, with seconds. The disk is
# 10^6 synthetic rays of a 1 W Lambertian disk of radius 50 mm, built into a model first.
# Usage: tests/bench/grey_box.sh BUILD_DIR [WIDTH HEIGHT REFERENCE [INTEGRATOR...]]
#        (default 160 160 1024 path bidirectional; Mitsuba from PyPI: pip install mitsuba)
set -euo pipefail
build=${1:?usage: grey_box.sh BUILD_DIR [WIDTH HEIGHT REFERENCE [INTEGRATOR...]]}
width=${2:-160} height=${3:-160} reference=${4:-1024}
shift $(( $# < 4 ? $# : 4 ))
integrators=("$@")
[ ${#integrators[@]} -gt 0 ] || integrators=(path bidirectional)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-grey-box.XXXXXX")
trap 'rm -rf "$work"' EXIT

"$build/converters/rayconv" synth disk radius=50 flux=1 --rays 1000000 --seed 3 \
  -o "$work/disk.tm25ray" > /dev/null
"$build/lightmodel/raymodel" build "$work/disk.tm25ray" -o "$work/disk.vdb" > /dev/null
"$build/tests/bench/box_convergence" "$here/grey_box/grey_box.pov" "$work" "$width" "$height" \
  "$reference" "${integrators[@]}"
if python3 -c "import mitsuba" 2> /dev/null; then
  python3 "$here/grey_box/mitsuba_grey_box.py" "$width" "$height" "$reference"
else
  echo "Mitsuba 3 not installed (pip install mitsuba): no comparison"
fi
