#!/usr/bin/env bash
# Parsing a scene that makes OBJECTS spheres through a macro called in a #while loop (random
# centres and radii from rand(), a pigment each), by raytrace and by POV-Ray 3.7 itself.
# Usage: tests/bench/parse_speed.sh BUILD_DIR [OBJECTS] [ROUNDS]   (default 1000000 objects, 5 rounds)
# Prints a table; figures go into issue notes, not into assertions.
#
# raytrace --parse-only reads the scene and builds its description (every instance with its
# transform and texture), then exits: its whole process is timed. POV-Ray cannot stop after
# parsing, so it renders one pixel with -D; its own "Parse Time" (from its statistics) is the
# comparator, and its whole process (which adds building its bounding hierarchy) is shown too.
# The two run in alternating rounds, so a change in the machine's speed hits both.
set -euo pipefail
build=${1:?usage: parse_speed.sh BUILD_DIR [OBJECTS] [ROUNDS]}
objects=${2:-1000000}
rounds=${3:-5}
raytrace="$build/tracer/raytrace"
[ -x "$raytrace" ] || { echo "parse_speed.sh: $raytrace not built" >&2; exit 1; }
command -v povray > /dev/null || { echo "parse_speed.sh: povray not installed (scripts/install-deps.sh)" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-parse.XXXXXX")
trap 'rm -rf "$work"' EXIT

cat > "$work/scene.pov" <<EOF
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Ball(P, R) sphere { P, R pigment { rgb <0.5, 0.5, 0.5> } } #end
#declare S = seed(1);
#declare I = 0;
#while (I < $objects)
  Ball(<rand(S), rand(S), rand(S)> * 100, 0.1 + 0.1 * rand(S))
  #declare I = I + 1;
#end
camera { location <50, 50, -100> look_at <50, 50, 50> }
light_source { <0, 200, -100> rgb 1 }
EOF

seconds_now() { date +%s.%N; }
minus() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a - b }'; }
ours=() theirs=() theirs_parse=()
for ((round = 1; round <= rounds; round++)); do
  start=$(seconds_now)
  "$raytrace" "$work/scene.pov" --parse-only > "$work/ours.log"
  ours+=("$(minus "$(seconds_now)" "$start")")
  start=$(seconds_now)
  (cd "$work" && povray +Iscene.pov +W1 +H1 -D -V +Oout.png > povray.log 2>&1)
  theirs+=("$(minus "$(seconds_now)" "$start")")
  theirs_parse+=("$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/povray.log")")
done
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
echo "objects: $objects, rounds: $rounds ($(nproc) cores)"
cat "$work/ours.log"
printf '%-44s %10s\n' "" "median s"
printf '%-44s %10.3f\n' "raytrace --parse-only (whole process)" "$(median "${ours[@]}")"
printf '%-44s %10.3f\n' "povray: its Parse Time" "$(median "${theirs_parse[@]}")"
printf '%-44s %10.3f\n' "povray: whole process (+ bounding, 1 pixel)" "$(median "${theirs[@]}")"
printf 'ratio raytrace / povray parse, per round:'
for ((i = 0; i < rounds; i++)); do awk -v a="${ours[$i]}" -v b="${theirs_parse[$i]}" 'BEGIN { printf " %.2f", a / b }'; done
echo
