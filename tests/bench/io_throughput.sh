#!/usr/bin/env bash
# Reading and converting a large TM-25 file against `cat FILE > /dev/null` of the same file,
# and peak memory at two ray counts (it should not grow with the count).
# Usage: tests/bench/io_throughput.sh BUILD_DIR [RAYS]      (default 10000000 rays)
# Prints a table; figures go into issue notes, not into assertions.
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
work=$(mktemp -d "${TMPDIR:-/tmp}/rayset-bench.XXXXXX")
shm=$(mktemp -d /dev/shm/rayset-bench.XXXXXX 2> /dev/null || true)
trap 'rm -rf "$work" ${shm:+"$shm"}' EXIT

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
  awk -v n="$1" -v s="$2" -v m="$3" -v b="$4" 'BEGIN{printf "%-44s %8.2f s %9.0f MB/s %8.1f MiB peak\n", n, s, b/1e6/(s>0?s:1e-9), m/1024}'
}

small=$((rays / 10))
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$rays" --seed 1 -o "$work/big.tm25ray"
"$rayconv" synth disk radius=1 flux=1 wavelength=550 --rays "$small" --seed 1 -o "$work/small.tm25ray"
bytes=$(stat -c %s "$work/big.tm25ray")
echo "file: $rays rays, $bytes bytes; $(nproc) cores"

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
read -r s m < <(measure "$rayconv" info "$work/big.tm25ray"); row "rayconv info" "$s" "$m" "$bytes"; info_s=$s
read -r s m < <(measure dd if="$work/big.tm25ray" of="$work/copy.tm25ray" bs=1M conv=fsync status=none); row "dd conv=fsync (write + fsync, no parsing)" "$s" "$m" "$bytes"; dd_s=$s
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.tm25ray"); row "rayconv convert tm25 -> tm25" "$s" "$m" "$bytes"; conv_s=$s
if [ -n "$shm" ]; then
  read -r s m < <(measure sh -c "cat '$work/big.tm25ray' > '$shm/copy.tm25ray'"); row "cat > tmpfs file" "$s" "$m" "$bytes"
  read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$shm/out.tm25ray"); row "rayconv convert tm25 -> tm25 on tmpfs" "$s" "$m" "$bytes"
  rm -f "$shm"/*.tm25ray
fi
read -r s m < <(measure "$rayconv" convert "$work/big.tm25ray" "$work/out.ray" --to lighttools); row "rayconv convert tm25 -> lighttools" "$s" "$m" "$bytes"
read -r s m2 < <(measure "$rayconv" info "$work/small.tm25ray"); row "rayconv info ($small rays)" "$s" "$m2" "$((bytes / 10))"
awk -v c="$cat_s" -v i="$info_s" -v v="$conv_s" -v d="$dd_s" \
  'BEGIN{printf "info at %.0f%% of cat throughput, convert at %.0f%% (at %.0f%% of dd conv=fsync)\n", 100*c/i, 100*c/v, 100*d/v}'
