#!/usr/bin/env bash
# The geometry scan: for each POV-Ray 3.7 sample scene (Debian package povray-examples) that
# raytrace renders, the fraction of pixels where POV-Ray and the renderer see the same object,
# both rendering the scene's flat-colour copy (every object statement one self-lit colour:
# tests/tracer/flat_colour_scene.h), 160 x 120, one ray through each pixel's centre. Needs
# `povray` and the compatibility scan's table (scripts/pov_compat.sh BUILD_DIR first).
#
# Usage: scripts/pov_geometry.sh [BUILD_DIR] [FILTER]
#   BUILD_DIR  where the tests were built (default: build)
#   FILTER     only scenes whose path under the examples folder contains it
# Writes BUILD_DIR/pov_geometry.tsv (pov_geometry's lines) and prints how many scenes agree on
# at least 99% of the pixels, and which shapes, CSG operations and cameras those use.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
filter=${2:-}
tool="$PWD/$build/tests/pov_geometry"
compat="$build/pov_compat.tsv"
examples=/usr/share/doc/povray/examples
[ -x "$tool" ] || { echo "pov_geometry: $tool not built (cmake --build $build)" >&2; exit 2; }
[ -f "$compat" ] || { echo "pov_geometry: $compat missing (scripts/pov_compat.sh $build)" >&2; exit 2; }
command -v povray > /dev/null || { echo "pov_geometry: povray missing (apt-get install povray)" >&2; exit 2; }

report="$PWD/$build/pov_geometry.tsv"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: > "$report"
# Scenes that render and need no .ini of their own (frames, clocks: POV-Ray would run them
# with other settings than the copy gets).
awk -F'\t' '$4 == 1 { print $2 }' "$compat" | while IFS= read -r relative; do
  case "$relative" in *"$filter"*) ;; *) continue ;; esac
  scene="$examples/$relative"
  [ -f "${scene%.pov}.ini" ] && continue
  if ! (cd "$work" && timeout 300 "$tool" "$scene" < /dev/null >> "$report" 2> "$work/err"); then
    printf 'error\t0\t0\t0\t%s\t%s\n' "$scene" "$(head -c 200 "$work/err" | tr '\n\t' '  ')" >> "$report"
  fi
done

awk -F'\t' '
  { total++ }
  $1 == "error" { errors++; next }
  $1 >= 0.99 { agree++ }
  END { printf "%d scenes: %d agree on at least 99%% of the pixels, %d below, %d not compared\n",
               total, agree, total - agree - errors, errors }' "$report"
echo
echo "Below 99%:"
awk -F'\t' '$1 != "error" && $1 < 0.99 { printf "  %s  %s\n", $1, $5 }' "$report" | sort -n
echo
echo "Not compared:"
awk -F'\t' '$1 == "error" { printf "  %s: %s\n", $5, substr($6, 1, 150) }' "$report"
echo
echo "Features of the agreeing scenes (scenes using each):"
features="cylinder cone disc torus polygon prism lathe sor superellipsoid height_field text blob
  isosurface sphere_sweep bicubic_patch quadric cubic quartic poly parametric julia_fractal
  merge intersection difference inverse clipped_by bounded_by"
cameras="orthographic fisheye ultra_wide_angle omnimax panoramic cylinder spherical mesh_camera"
for f in $features; do
  printf '  %-16s %d\n' "$f" "$(awk -F'\t' -v f=" $f " '$1 != "error" && $1 >= 0.99 && index($6 " ", f)' "$report" | wc -l)"
done
for c in $cameras; do
  printf '  camera %-9s %d\n' "$c" "$(awk -F'\t' -v f=" camera:$c " '$1 != "error" && $1 >= 0.99 && index($6 " ", f)' "$report" | wc -l)"
done
