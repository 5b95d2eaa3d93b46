#!/usr/bin/env bash
# Reading and converting a large TM-25 file against `cat FILE > /dev/null` of the same file,
# and peak memory at two ray counts (it should not grow with the count).
# Usage: tests/bench/io_throughput.sh BUILD_DIR [RAYS]      (default 10000000 rays)
# Prints a table; figures go into issue notes, not into assertions.
set -euo pipefail
build=${1:?usage: io_throughput.sh BUILD_DIR [RAYS]}
rays=${2:-10000000}
rayconv="$build/converters/rayconv"
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

# wall seconds and peak RSS (KiB) of a command, best of three runs (warm page cache)
measure() {
  local best="" rss=""
  for _ in 1 2 3; do
    /usr/bin/time -f "%e %M" -o "$work/t" "$@" > /dev/null 2>&1
    read -r s m < "$work/t"
    if [ -z "$best" ] || awk "BEGIN{exit !($s < $best)}"; then best=$s; rss=$m; fi
  done
  echo "$best $rss"
}

row() { # name seconds rss bytes
  awk -v n="$1" -v s="$2" -v m="$3" -v b="$4" 'BEGIN{printf "%-34s %8.2f s %9.0f MB/s %8.1f MiB peak\n", n, s, b/1e6/(s>0?s:1e-9), m/1024}'
}

small=$((rays / 10))
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$rays" --seed 1 -o "$work/big.tm25ray"
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$small" --seed 1 -o "$work/small.tm25ray"
bytes=$(stat -c %s "$work/big.tm25ray")
echo "file: $rays rays, $bytes bytes; $(nproc) cores"

read -r s m < <(measure cat "$work/big.tm25ray"); row "cat > /dev/null" "$s" "$m" "$bytes"; cat_s=$s
read -r s m < <(measure sh -c "cat '$work/big.tm25ray' | wc -c"); row "cat | wc -c (bytes through a pipe)" "$s" "$m" "$bytes"
read -r s m < <(measure "$rayconv" info "$work/big.tm25ray"); row "rayconv info" "$s" "$m" "$bytes"; info_s=$s
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.tm25ray"); row "rayconv convert tm25 -> tm25" "$s" "$m" "$bytes"; conv_s=$s
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.ray" --to lighttools); row "rayconv convert tm25 -> lighttools" "$s" "$m" "$bytes"
read -r s m2 < <(measure "$rayconv" info "$work/small.tm25ray"); row "rayconv info ($small rays)" "$s" "$m2" "$((bytes / 10))"
awk -v c="$cat_s" -v i="$info_s" -v v="$conv_s" 'BEGIN{printf "info at %.0f%% of cat throughput, convert at %.0f%%\n", 100*c/i, 100*c/v}'
