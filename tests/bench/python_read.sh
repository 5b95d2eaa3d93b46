#!/usr/bin/env bash
# Reading a TM-25 file into numpy (rayset.read_rays) against the C++ reader's rate on the same
# file (`rayconv info`, which reads in parts on every core and summarises), in alternating
# rounds so that a slow spell of a shared machine hits both alike.
# Usage: tests/bench/python_read.sh BUILD_DIR [RAYS] [PYTHON]
#   (default 10000000 rays; PYTHON: one with rayset installed, default BUILD_DIR/venv/bin/python)
# Prints each round and the median ratio (Python's rate over the C++ one); figures go into issue
# notes, not into assertions.
set -euo pipefail
build=${1:?usage: python_read.sh BUILD_DIR [RAYS] [PYTHON]}
rays=${2:-10000000}
python=${3:-$build/venv/bin/python}
rayconv="$build/converters/rayconv"
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
file="$work/disk.tm25ray"
"$rayconv" synth disk --rays "$rays" --seed 1 -o "$file" > /dev/null

# Seconds of one run, from the clock: the C++ tool as a process, Python timed inside (the
# interpreter's start and `import rayset` are left out; the arrays are allocated and filled).
cpp_seconds() {
  local start end
  start=$(date +%s%N)
  "$rayconv" info "$file" > /dev/null
  end=$(date +%s%N)
  awk -v ns=$((end - start)) 'BEGIN{printf "%.4f\n", ns / 1e9}'
}
py_seconds() {
  "$python" - "$file" << 'PY'
import sys, time
import rayset
start = time.perf_counter()
rays = rayset.read_rays(sys.argv[1])
seconds = time.perf_counter() - start
assert len(rays) == rays.header["ray_count"]
print(f"{seconds:.4f}")
PY
}

cpp_seconds > /dev/null  # the page cache warm for both
rounds=${ROUNDS:-5}
ratios=()
printf "%-6s %12s %12s %12s %12s %8s\n" round "C++ s" "C++ Mrays/s" "Python s" "Py Mrays/s" ratio
for round in $(seq "$rounds"); do
  if [ $((round % 2)) -eq 1 ]; then
    c=$(cpp_seconds); p=$(py_seconds)
  else
    p=$(py_seconds); c=$(cpp_seconds)
  fi
  ratio=$(awk -v c="$c" -v p="$p" 'BEGIN{printf "%.3f", c / p}')
  ratios+=("$ratio")
  awk -v r="$round" -v c="$c" -v p="$p" -v n="$rays" -v q="$ratio" \
    'BEGIN{printf "%-6s %12.3f %12.1f %12.3f %12.1f %8s\n", r, c, n / c / 1e6, p, n / p / 1e6, q}'
done
median=$(printf "%s\n" "${ratios[@]}" | sort -g | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}')
echo "median ratio (Python rate / C++ rate): $median   (target: at least 0.5)"
