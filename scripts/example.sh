#!/usr/bin/env bash
# The bundled example: synthesise the paper's 39-LED cluster (chips of three colours in rings
# of 1 + 6 + 12 + 20), inspect it, convert it to LightTools, compute its far-field photometry
# as IES and EULUMDAT, build its light model, and render the paper's box lit by it
# (examples/led_box.pov): Figures 4-7 with the model, Figure 1 with the naive ray set in the
# same time. Outputs go to out/example/. Rendering takes 3 minutes on 2 cores.
# Usage: scripts/example.sh        (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build --target rayconv raymodel raytrace -j "$(nproc)"
rayconv=build/converters/rayconv
out=out/example
mkdir -p "$out"

echo "== synthesise the 39-chip cluster (1 million rays)"
"$rayconv" synth cluster rings=1,6,12,20 chip=1 pitch=2 flux=1 wavelength=630,530,460 \
  --rays 1000000 --seed 1 -o "$out/cluster.tm25ray"
echo "== what the ray file holds"
"$rayconv" info "$out/cluster.tm25ray"
echo "== convert to LightTools binary and back to TM-25"
"$rayconv" convert "$out/cluster.tm25ray" "$out/cluster.ray" --to lighttools
"$rayconv" convert "$out/cluster.ray" "$out/cluster-again.tm25ray"
"$rayconv" info "$out/cluster-again.tm25ray" | grep -E "^(rays|flux|  )"
echo "== far-field photometry (type C, 5 x 2.5 degree cells)"
"$rayconv" farfield "$out/cluster.tm25ray" -o "$out/cluster.ies"
"$rayconv" convert "$out/cluster.ies" "$out/cluster.ldt"
"$rayconv" info "$out/cluster.ies"
echo "== the paper's light-source model of the cluster (docs/light-model.md)"
build/lightmodel/raymodel build "$out/cluster.tm25ray" -o "$out/cluster.vdb"
seconds=${EXAMPLE_SECONDS:-90}
echo "== the paper's box lit by the cluster through its model: Figures 4-7 ($seconds s)"
build/tracer/raytrace examples/led_box.pov +L"$out" +W640 +H480 --time "$seconds" -o "$out/led_box.exr"
echo "== Figure 1: the same box with the naive ray set (the rays as photons), same time"
build/tracer/raytrace examples/led_box.pov +L"$out" +W640 +H480 --time "$seconds" --naive-sources -o "$out/naive.exr"
cat <<EOF
The paper's figures in $out/ (EXR: linear radiance and luminance Y in cd/m^2; PNG previews):
  Figure 1  naive.png                      naive ray set: source invisible, primary light noisy
  Figure 4  led_box.direct_visibility.png  the chips as the camera sees them (the model's body)
  Figure 5  led_box.primary.png            primary light (light + BSDF sampling, MIS)
  Figure 6  led_box.secondary.png          secondary light (photons after a scattering)
  Figure 7  led_box.png                    the full image
EOF
