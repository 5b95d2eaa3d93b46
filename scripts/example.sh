#!/usr/bin/env bash
# The bundled example: synthesise the paper's 39-LED cluster (chips of three colours in rings
# of 1 + 6 + 12 + 20), inspect it, convert it to LightTools, and compute its far-field
# photometry as IES and EULUMDAT. Outputs go to out/example/.
# Usage: scripts/example.sh        (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build --target rayconv raymodel -j "$(nproc)"
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
echo "Outputs in $out/"
