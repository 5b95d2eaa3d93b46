#!/usr/bin/env bash
# Regenerates docs/gallery/: every rayview view rendered off-screen from the bundled example
# (the synthetic 39-chip cluster) and the real files in ../shared/data when they are there.
# Usage: scripts/gallery.sh        (after a build; runs under xvfb-run when there is no display)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
cmake --build "$build" --target rayview rayconv raymodel raytrace -j 2
out=docs/gallery
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a "$@"; fi; }
view() { run "$build/viz/rayview" "$@" --size 900x675 >/dev/null; }

"$build/converters/rayconv" synth cluster --rays 1000000 --seed 7 -o "$work/cluster.tm25ray" >/dev/null
"$build/lightmodel/raymodel" build "$work/cluster.tm25ray" -o "$work/cluster.vdb" >/dev/null
mkdir -p "$out"
view "$work/cluster.vdb" --show spheres --png "$out/cluster-spheres.png"
view "$work/cluster.vdb" --show density --png "$out/cluster-density.png"
view "$work/cluster.vdb" --show flux --png "$out/cluster-flux.png"
view "$work/cluster.vdb" --show diagram --cell 2,2,0 --png "$out/cluster-diagram.png"
view "$work/cluster.tm25ray" --show rays --points 3000 --png "$out/cluster-rays.png"
view "$work/cluster.tm25ray" --show polar --png "$out/cluster-polar.png"
# The same model's spheres with its rays in ParaView, through the reader plugin in the pvpython
# scripts/install-deps.sh unpacks (python/README.md, "ParaView").
pvpython="$build/paraview/usr/bin/pvpython"
if [ -x "$pvpython" ]; then
  cmake --build "$build" --target _rayset -j 2
  PYTHONPATH="$(cd "$build" && pwd)/python" run "$pvpython" python/paraview/screenshot.py \
    "$work/cluster.vdb" "$work/cluster.tm25ray" "$out/paraview-model-rays.png"
fi
# The tracer's image view: POV-Ray's Cornell box rendered by raytrace, its luminance layer Y.
"$build/tracer/raytrace" tests/tracer/scenes/cornell.pov +W320 +H240 --passes 64 --no-png -q \
  -o "$work/cornell.exr" >/dev/null
view "$work/cornell.exr" --show image --layer Y --png "$out/cornell-luminance.png"

data=../shared/data
if [ -d "$data" ]; then
  blue=$data/rayfiles/rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY
  view "$blue" --show farfield --png "$out/osram-blue-farfield.png"
  view "$blue" --show polar --png "$out/osram-blue-polar.png"
  view "$data/photometry/ABSOLUTE_LED.ies" --show farfield --png "$out/ies-farfield.png"
  view "$blue" --show polar --compare "$work/cluster.tm25ray" --png "$out/compare-polar.png"
fi
# The paper's figures: the bundled example's box (examples/led_box.pov) at 320 x 240, 40 s
# each (scripts/example.sh renders them at 640 x 480 into out/example/).
"$build/converters/rayconv" synth cluster rings=1,6,12,20 chip=1 pitch=2 flux=1 wavelength=630,530,460 \
  --rays 1000000 --seed 1 -o "$work/cluster.tm25ray" > /dev/null
for mode in model naive; do
  flag=""; [ "$mode" = naive ] && flag=--naive-sources
  "$build/tracer/raytrace" examples/led_box.pov +L"$work" +W320 +H240 --time 40 -q $flag -o "$work/$mode.exr"
done
cp "$work/naive.png" "$out/paper-fig1-naive.png"
cp "$work/model.direct_visibility.png" "$out/paper-fig4-direct-visibility.png"
cp "$work/model.primary.png" "$out/paper-fig5-primary.png"
cp "$work/model.secondary.png" "$out/paper-fig6-secondary.png"
cp "$work/model.png" "$out/paper-fig7-full.png"
echo "gallery written to $out"
