#!/usr/bin/env bash
# The compatibility scan: runs raytrace over POV-Ray 3.7's sample scenes (Debian package
# povray-examples) and prints, per folder, how many parse completely, how many render (32 x 24,
# one pass), and what stops the rest ("not supported: FEATURE", or the error).
#
# Usage: scripts/pov_compat.sh [BUILD_DIR] [FILTER]
#   BUILD_DIR  where raytrace was built (default: build)
#   FILTER     only scenes whose path under the examples folder contains it (e.g. "language/")
# Writes BUILD_DIR/pov_compat.tsv (one row per scene: folder, scene, parsed, rendered, reason).
# Each scene runs in a scratch folder it may write to (some write files with #fopen).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
filter=${2:-}
raytrace="$PWD/$build/tracer/raytrace"
examples=/usr/share/doc/povray/examples
[ -x "$raytrace" ] || { echo "pov_compat: $raytrace not built (cmake --build $build)" >&2; exit 2; }
[ -d "$examples" ] || { echo "pov_compat: $examples missing (apt-get install povray-examples)" >&2; exit 2; }

report="$build/pov_compat.tsv"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: > "$report"

# The reason a run stopped: "not supported: FEATURE" without its location, else the error.
reason_of() {
  local text
  text=$(grep -m1 -oE "raytrace: error: .*|timeout \(.*" "$1" || true)
  text=${text#raytrace: error: }
  echo "$text" | sed -E 's/ at [^ ]+:[0-9]+:[0-9]+.*$//' | cut -c1-110
}

while IFS= read -r scene; do
  relative=${scene#"$examples"/}
  case "$relative" in *"$filter"*) ;; *) continue ;; esac
  folder=$(dirname "$relative" | cut -d/ -f1)
  rm -rf "$work/run" && mkdir "$work/run"
  # A scene with an .ini of its own (its frames, say) runs with it, as POV-Ray's users run it.
  ini=()
  [ -f "${scene%.pov}.ini" ] && ini=("${scene%.pov}.ini")
  parsed=0 rendered=0 reason=""
  if (cd "$work/run" && timeout 120 "$raytrace" "${ini[@]}" "$scene" --parse-only --allow-write . \
        > "$work/out" 2>&1); then
    parsed=1
    if (cd "$work/run" && timeout 300 "$raytrace" "${ini[@]}" "$scene" +W32 +H24 --passes 1 -q \
          --allow-write . -o "$work/run/image.exr" > "$work/out" 2>&1); then
      rendered=1
    else
      [ $? -eq 124 ] && echo "timeout (300 s rendering)" >> "$work/out"
      reason=$(reason_of "$work/out")
    fi
  else
    [ $? -eq 124 ] && echo "timeout (120 s parsing)" >> "$work/out"
    reason=$(reason_of "$work/out")
  fi
  printf '%s\t%s\t%d\t%d\t%s\n' "$folder" "$relative" "$parsed" "$rendered" "$reason" >> "$report"
done < <(find "$examples" -name '*.pov' | sort)

printf '%-12s %7s %15s %15s\n' folder scenes parse render
awk -F'\t' '
  { scenes[$1]++; parsed[$1] += $3; rendered[$1] += $4 }
  END { for (f in scenes) printf "%-12s %7d %7d (%3.0f%%) %7d (%3.0f%%)\n", f, scenes[f], parsed[f],
                                 100 * parsed[f] / scenes[f], rendered[f], 100 * rendered[f] / scenes[f] }' \
  "$report" | sort
awk -F'\t' '{ total++; p += $3; r += $4 }
  END { printf "%-12s %7d %7d (%3.0f%%) %7d (%3.0f%%)\n", "all", total, p, 100 * p / total, r, 100 * r / total }' \
  "$report"
echo
echo "What stops the scenes that do not parse:"
awk -F'\t' '!$3 { print $5 }' "$report" | sort | uniq -c | sort -rn | head -40
echo
echo "What stops the scenes that parse but do not render:"
awk -F'\t' '$3 && !$4 { print $5 }' "$report" | sort | uniq -c | sort -rn | head -40
