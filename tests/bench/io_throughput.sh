#!/usr/bin/env bash
# Reading and converting a large TM-25 file against `cat FILE > /dev/null` of the same file,
# and peak memory at two ray counts (it should not grow with the count).
# Usage: tests/bench/io_throughput.sh BUILD_DIR [RAYS]      (default 10000000 rays)
# Prints a table; figures go into issue notes, not into assertions.
#
# Reading is timed three ways: `read_rays` (tests/bench) reads every ray through the library's
# reader (detect, decode, validate, sum the fluxes) in parts on every core, as `rayconv info`
# does, and does nothing else; `read_rays --sequential` reads them as records in file order,
# as `rayconv convert` and the other commands do; `rayconv info` reads them in parts and also
# summarises them (bounding box, wavelengths, the direction coverage of 20000 cells and the
# mean direction).
#
# Comparators: reading is set against `cat > /dev/null` (a copy out of the page cache) and
# against a plain loop summing the file's 32-bit words through mmap (what touching every byte
# costs at all; compiled here if a C++ compiler is at hand). Converting writes the file and
# fsyncs it before renaming it into place, so it is also set against `dd conv=fsync`, which
# does the same with no work per ray; the tmpfs rows take the disk out of both.
set -euo pipefail
build=${1:?usage: io_throughput.sh BUILD_DIR [RAYS]}
rays=${2:-10000000}
rayconv="$build/converters/rayconv"
read_rays="$build/tests/bench/read_rays"
[ -x "$read_rays" ] || { echo "io_throughput.sh: $read_rays not built (configure with RAYSET_BUILD_BENCHMARKS=ON and Google Benchmark installed)" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-bench.XXXXXX")
shm=$(mktemp -d /dev/shm/rayset-bench.XXXXXX 2> /dev/null || true)
trap 'rm -rf "$work" ${shm:+"$shm"}' EXIT

# Wall time in milliseconds (from the clock, not /usr/bin/time's 10 ms steps) and peak RSS
# (KiB) of one run of a command; the page cache is warm after the first.
run_once() {
  local start end
  start=$(date +%s%N)
  /usr/bin/time -f "%M" -o "$work/rss" "$@" > /dev/null 2>&1
  end=$(date +%s%N)
  echo "$(( (end - start) / 1000 )) $(cat "$work/rss")"
}

# keep_least VAR VALUE: VAR becomes VALUE if it is empty or larger.
keep_least() {
  local -n least=$1
  if [ -z "$least" ] || [ "$2" -lt "$least" ]; then least=$2; fi
}

# Best (least) wall time of $runs runs, as seconds, and the largest peak RSS seen.
runs=${RUNS:-7}
measure() {
  local best="" rss=0 us m
  for _ in $(seq "$runs"); do
    read -r us m < <(run_once "$@")
    keep_least best "$us"
    if [ "$m" -gt "$rss" ]; then rss=$m; fi
  done
  awk -v us="$best" -v m="$rss" 'BEGIN{printf "%.4f %d\n", us / 1e6, m}'
}

# cat and a reading command in alternation, so that a slow spell of a shared machine hits both
# alike: the best of each and the median of the per-round ratios (cat's time over the command's).
paired() { # file command...
  local file=$1 ratios=() best_cat="" best_cmd="" c i
  shift
  for _ in $(seq "$runs"); do
    read -r c _ < <(run_once cat "$file")
    read -r i _ < <(run_once "$@" "$file")
    ratios+=("$(awk -v c="$c" -v i="$i" 'BEGIN{print c / i}')")
    keep_least best_cat "$c"
    keep_least best_cmd "$i"
  done
  local median
  median=$(printf "%s\n" "${ratios[@]}" | sort -g | awk '{v[NR]=$1} END{print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}')
  echo "$best_cat $best_cmd $median"
}

row() { # name seconds rss bytes
  awk -v n="$1" -v s="$2" -v m="$3" -v b="$4" 'BEGIN{printf "%-44s %8.3f s %9.0f MB/s %8.1f MiB peak\n", n, s, b/1e6/(s>0?s:1e-9), m/1024}'
}

small=$((rays / 10))
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$rays" --seed 1 -o "$work/big.tm25ray"
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$small" --seed 1 -o "$work/small.tm25ray"
bytes=$(stat -c %s "$work/big.tm25ray")
echo "file: $rays rays, $bytes bytes; $(nproc) cores; best of $runs runs (RUNS=...); load: $(cut -d' ' -f1-3 /proc/loadavg)"

floor=""
if command -v c++ > /dev/null; then
  cat > "$work/floor.cpp" << 'EOF'
// Sums a file's 32-bit words through mmap: the least any reader that looks at every byte pays.
#include <cstdint>
#include <cstdio>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
int main(int, char** argv) {
  int fd = open(argv[1], O_RDONLY);
  struct stat st;
  if (fd < 0 || fstat(fd, &st) != 0) return 1;
  const uint32_t* words = static_cast<const uint32_t*>(mmap(nullptr, st.st_size, PROT_READ, MAP_PRIVATE, fd, 0));
  madvise(const_cast<uint32_t*>(words), st.st_size, MADV_SEQUENTIAL);
  uint64_t sum = 0;
  for (size_t i = 0; i < size_t(st.st_size) / 4; ++i) sum += words[i];
  std::printf("%llu\n", static_cast<unsigned long long>(sum));
}
EOF
  c++ -O3 -o "$work/floor" "$work/floor.cpp" && floor="$work/floor"
fi

read -r s m < <(measure cat "$work/big.tm25ray"); row "cat > /dev/null" "$s" "$m" "$bytes"; cat_s=$s
if [ -n "$floor" ]; then read -r s m < <(measure "$floor" "$work/big.tm25ray"); row "sum of 32-bit words (mmap, one thread)" "$s" "$m" "$bytes"; fi
read -r s m < <(measure sh -c "cat '$work/big.tm25ray' | wc -c"); row "cat | wc -c (bytes through a pipe)" "$s" "$m" "$bytes"
read -r s m < <(measure "$read_rays" "$work/big.tm25ray"); row "read_rays (decode + validate)" "$s" "$m" "$bytes"; read_s=$s
read -r s m < <(measure "$read_rays" --sequential "$work/big.tm25ray"); row "read_rays --sequential (records in order)" "$s" "$m" "$bytes"; sequential_s=$s
read -r s m < <(measure "$rayconv" info "$work/big.tm25ray"); row "rayconv info (read + summarise)" "$s" "$m" "$bytes"; info_s=$s
read -r s m < <(measure dd if="$work/big.tm25ray" of="$work/copy.tm25ray" bs=1M conv=fsync status=none); row "dd conv=fsync (write + fsync, no parsing)" "$s" "$m" "$bytes"; dd_s=$s
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.tm25ray"); row "rayconv convert tm25 -> tm25" "$s" "$m" "$bytes"; conv_s=$s
if [ -n "$shm" ]; then
  read -r s m < <(measure sh -c "cat '$work/big.tm25ray' > '$shm/copy.tm25ray'"); row "cat > tmpfs file" "$s" "$m" "$bytes"
  read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$shm/out.tm25ray"); row "rayconv convert tm25 -> tm25 on tmpfs" "$s" "$m" "$bytes"
  rm -f "$shm"/*.tm25ray
fi
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.ray" --to lighttools); row "rayconv convert tm25 -> lighttools" "$s" "$m" "$bytes"
read -r s m2 < <(measure "$rayconv" info "$work/small.tm25ray"); row "rayconv info ($small rays)" "$s" "$m2" "$((bytes / 10))"
percent() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.0f%%", 100 * a / b}'; }
for reader in read_rays "read_rays --sequential" info; do
  case $reader in
    read_rays) best=$read_s; cmd=("$read_rays") ;;
    "read_rays --sequential") best=$sequential_s; cmd=("$read_rays" --sequential) ;;
    *) best=$info_s; cmd=("$rayconv" info) ;;
  esac
  read -r pc pi ratio < <(paired "$work/big.tm25ray" "${cmd[@]}")
  awk -v r="$reader" -v c="$cat_s" -v b="$best" -v n="$runs" -v pc="$pc" -v pi="$pi" -v m="$ratio" \
    'BEGIN{printf "%s at %.0f%% of cat throughput (best times); in %d alternating rounds: best cat %.3f s, best %s %.3f s, median of the rounds\x27 ratios %.0f%%\n", r, 100*c/b, n, pc/1e6, r, pi/1e6, 100*m}'
done
echo "convert at $(percent "$cat_s" "$conv_s") of cat > /dev/null, at $(percent "$dd_s" "$conv_s") of dd conv=fsync"

# Where the time goes, if perf is installed: CPU time (all threads) against cat's. With two
# cores, a reader's wall time is at least (its CPU time) / 2, and its CPU time is cat's copy
# plus the decoding and validating (and for info, summarising).
if command -v perf > /dev/null && perf stat -e task-clock true > /dev/null 2>&1; then
  cpu_ms() { perf stat -x, -e task-clock "$@" 2>&1 > /dev/null | awk -F, '/task-clock/{print $1}'; }
  best_cat_cpu="" best_read_cpu="" best_info_cpu=""
  for _ in $(seq "$runs"); do
    keep_least best_cat_cpu "$(cpu_ms cat "$work/big.tm25ray" | cut -d. -f1)"
    keep_least best_read_cpu "$(cpu_ms "$read_rays" "$work/big.tm25ray" | cut -d. -f1)"
    keep_least best_info_cpu "$(cpu_ms "$rayconv" info "$work/big.tm25ray" | cut -d. -f1)"
  done
  echo "CPU time (perf task-clock, all threads, best of $runs): cat $best_cat_cpu ms, read_rays $best_read_cpu ms, rayconv info $best_info_cpu ms"
fi
