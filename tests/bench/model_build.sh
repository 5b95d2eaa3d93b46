#!/usr/bin/env bash
# Build time, peak memory and model size of `raymodel build` for the 39-chip cluster at 1, 10
# and 30 million rays (the issue's targets: 10 million rays in under 20 s on 2 cores; memory
# bounded by the lattices; model under 5% of the ray file at 10 million rays).
# Usage: tests/bench/model_build.sh BUILD_DIR [COUNTS...]     (default 1000000 10000000 30000000)
set -euo pipefail
build=${1:?usage: model_build.sh BUILD_DIR [COUNTS...]}
shift
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(1000000 10000000 30000000)
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-model-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
printf "%-10s %9s %10s %12s %12s %8s %8s\n" rays seconds "peak MiB" "rays bytes" "model bytes" ratio spheres
for n in "${counts[@]}"; do
  "$build/converters/rayconv" synth cluster --rays "$n" --seed 1 -o "$work/c.tm25ray" > /dev/null
  /usr/bin/time -f "%e %M" -o "$work/t" "$build/lightmodel/raymodel" build "$work/c.tm25ray" -o "$work/c.vdb" --json > "$work/j"
  read -r s m < "$work/t"
  rb=$(stat -c %s "$work/c.tm25ray"); mb=$(stat -c %s "$work/c.vdb")
  sp=$(python3 -c "import json,sys; print(json.load(open('$work/j'))['spheres'])")
  awk -v n="$n" -v s="$s" -v m="$m" -v rb="$rb" -v mb="$mb" -v sp="$sp" \
    'BEGIN{printf "%-10d %9.2f %10.1f %12d %12d %7.2f%% %8d\n", n, s, m/1024, rb, mb, 100*mb/rb, sp}'
  rm -f "$work/c.tm25ray" "$work/c.vdb"
done
