#!/usr/bin/env bash
# Coverage-guided fuzzing of the readers of untrusted files (fuzz/README.md): builds the libFuzzer
# harnesses with clang in build-fuzz/, makes their seed corpora, runs each harness for SECONDS
# or 10^7 executions, whichever comes first, and prints one line per harness. Exits non-zero
# when a harness crashed, hung or ran out of memory; the input that did it is in
# build-fuzz/crashes/<harness>/ and the harness's output in build-fuzz/logs/<harness>.log.
# Replay an input with build-fuzz/fuzz/fuzz_<harness> FILE.
# Usage: scripts/fuzz.sh SECONDS [HARNESS...]     (default: every harness, one after the other)
#   harnesses: the names of fuzz/*_fuzzer.cpp (tm25, ies, scene, mesh, model, checkpoint, ...)
#   RAYSET_SHARED_DATA: folder of the real sample files (default ../shared/data)
#   RAYSET_FUZZ_TIMEOUT: seconds of wall time an input may take (default 10); raise it when the
#     machine is shared, where a starved process takes that long over inputs that take one
set -euo pipefail

# Inside a function, which bash reads whole before running it: a run takes long, and an edit of
# this file meanwhile must not change what the run does.
main() {
  cd "$(dirname "$0")/.."

  if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]]; then
    sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
  fi
  seconds=$1
  shift

  build=build-fuzz
  shared=${RAYSET_SHARED_DATA:-../shared/data}
  # -O1 -g1, as the sanitizer tree of scripts/test.sh: half the compile time of -O2 -g, and
  # reports still name the function and line.
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DRAYSET_CONVERTERS_ONLY=ON -DRAYSET_FUZZ=ON >/dev/null

  # Every harness the tree has (those of the OBJ, model and checkpoint readers need the Debian
  # packages of tinyobjloader, OpenVDB and Embree), or those named.
  configured() { [ -d "$build/fuzz/CMakeFiles/fuzz_$1.dir" ]; }
  all=()
  for source in fuzz/*_fuzzer.cpp; do
    name=$(basename "$source" _fuzzer.cpp)
    configured "$name" && all+=("$name")
  done
  harnesses=("${@:-${all[@]}}")
  for h in "${harnesses[@]}"; do
    configured "$h" || { echo "fuzz.sh: no harness '$h' in $build (${all[*]})" >&2; exit 2; }
  done
  # A harness may have a tool of its own that writes its seed (fuzz_<harness>_seed FILE).
  targets=(fuzz_seeds)
  for h in "${harnesses[@]}"; do
    targets+=("fuzz_$h")
    configured "${h}_seed" && targets+=("fuzz_${h}_seed")
  done
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"

  # Seeds: the ray and photometry files fuzz_seeds makes (from ../shared/data when present), the
  # scenes of the tests and examples, and the inputs of earlier findings.
  seeds=$build/seeds
  rm -rf "$seeds"
  "$build/fuzz/fuzz_seeds" "$seeds" "$shared"
  for h in "${harnesses[@]}"; do
    if configured "${h}_seed"; then
      mkdir -p "$seeds/$h"
      "$build/fuzz/fuzz_${h}_seed" "$seeds/$h/seed"
    fi
  done
  mkdir -p "$seeds/scene"
  while IFS= read -r scene; do
    cp "$scene" "$seeds/scene/$(echo "$scene" | tr / _)"
  done < <(find tests examples -name '*.pov' -o -name '*.inc')

  # The largest input each harness is given: a TM-25 header alone is 36288 bytes and the smallest
  # model file about 100 kB; scenes and text files need no more than a few kilobytes to reach
  # every construct.
  max_len() {
    case $1 in
      model) echo 131072 ;;
      tm25 | ray_detect) echo 65536 ;;
      scene) echo 16384 ;;
      *) echo 8192 ;;
    esac
  }

  # The last value of "key: N" (libFuzzer's status lines and final stats) in a log, or "-".
  last_value() {
    local value
    value=$(grep -o "$1 *[0-9]*" "$2" | tail -n 1 | grep -o '[0-9]*$' || true)
    echo "${value:--}"
  }

  mkdir -p "$build/logs"
  failed=()
  summary=()
  for h in "${harnesses[@]}"; do
    corpus=$build/corpus/$h
    crashes=$build/crashes/$h
    log=$build/logs/$h.log
    mkdir -p "$corpus" "$crashes"
    inputs=("$corpus")
    [ -d "$seeds/$h" ] && inputs+=("$seeds/$h")
    [ -d "tests/fuzz/regressions/$h" ] && inputs+=("tests/fuzz/regressions/$h")
    options=(-max_total_time="$seconds" -runs=10000000 -timeout="${RAYSET_FUZZ_TIMEOUT:-10}"
      -rss_limit_mb=2048
      -max_len="$(max_len "$h")"
      -artifact_prefix="$crashes/" -print_final_stats=1)
    [ -f "fuzz/dictionaries/$h.dict" ] && options+=(-dict="fuzz/dictionaries/$h.dict")
    before=$(ls "$crashes" | wc -l)
    echo "fuzz.sh: $h for ${seconds}s ($log)"
    status=0
    UBSAN_OPTIONS=print_stacktrace=1 "$build/fuzz/fuzz_$h" "${options[@]}" "${inputs[@]}" \
      >"$log" 2>&1 || status=$?
    found=$(($(ls "$crashes" | wc -l) - before))
    if [ "$status" -ne 0 ] || [ "$found" -gt 0 ]; then
      failed+=("$h")
      [ "$found" -gt 0 ] || found="exit $status"
    fi
    summary+=("$(printf '%-18s %12s %8s %7s %9s %7s %s' "$h" \
      "$(last_value 'stat::number_of_executed_units:' "$log")" \
      "$(last_value 'stat::average_exec_per_sec:' "$log")" \
      "$(last_value 'cov:' "$log")" "$(last_value 'ft:' "$log")" \
      "$(last_value 'corp:' "$log")" "$found")")
  done

  printf '%-18s %12s %8s %7s %9s %7s %s\n' harness executions exec/s edges features corpus crashes
  printf '%s\n' "${summary[@]}"
  if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz.sh: ${failed[*]} failed: inputs in $build/crashes/<harness>/," \
      "output in $build/logs/" >&2
    exit 1
  fi
}

main "$@"
