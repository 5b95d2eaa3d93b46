#!/usr/bin/env bash
# The CMake package from outside: installs the build tree into a scratch prefix, builds
# examples/consumer against that copy only (find_package(rayset CONFIG)), compiles each public
# header (P/include/rayset/*.h) alone against it, and runs the consumer on the model
# of a Lambertian disk (radius 1 mm, 1 W). Its figures against closed forms: the model's flux is
# the rays' (1 W to float rounding), the mean photon flux is that flux (the model samples photons
# in proportion to flux, so each carries the same flux / pdf: equal to 1e-6 of it, the printed
# standard error is about 0), and the irradiance 100 mm above the disk is 1 / (pi (100^2 + 1^2)) W/mm^2 within
# 2% (the model's far-field error).
# Usage: consumer_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1 build_dir=$2
work=$build_dir/package-test
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
# Nothing of the build tree may be reachable: only the installed copy.
cmake -S "$source_dir/examples/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/consumer" > "$work/build.log"
# Each public header compiles alone, the first include of a file of its own, against the installed
# copy and linked to the library its top comment names ("Link rayset::NAME"): a header that
# leans on something its users would have to include first, or names the wrong library, fails.
headers=$work/headers
mkdir -p "$headers"
{
  echo 'cmake_minimum_required(VERSION 3.22)'
  echo 'project(rayset_public_headers LANGUAGES C CXX)'
  echo 'set(CMAKE_CXX_STANDARD 17)'
  echo 'set(CMAKE_CXX_STANDARD_REQUIRED ON)'
  echo 'find_package(rayset CONFIG REQUIRED)'
  for header in "$work/prefix/include/rayset/"*.h; do
    name=$(basename "$header" .h)
    library=$(grep -o -m1 'Link rayset::[a-z_]*' "$header" | cut -d' ' -f2) ||
      { echo "$header: its top comment names no library (Link rayset::NAME)" >&2; exit 1; }
    echo "#include <rayset/$name.h>" > "$headers/$name.cpp"
    echo "add_library(header_$name OBJECT $name.cpp)"
    echo "target_link_libraries(header_$name PRIVATE $library)"
  done
} > "$headers/CMakeLists.txt"
cmake -S "$headers" -B "$headers/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/headers-configure.log"
cmake --build "$headers/build" > "$work/headers-build.log"
echo "public headers compile alone: $(cd "$work/prefix/include/rayset" && echo *.h)"
# Images are read through a module loaded on the first image (image_reader_module.h), found
# through the run path: the installed raytrace renders a PNG and then a scene that maps it, and
# a project linking rayset::scene_language parses that scene, both failing if it is not found.
cat > "$work/gradient.pov" <<'POV'
#version 3.7;
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }
plane { z, 0 pigment { gradient x } finish { emission 1 ambient 0 diffuse 0 } }
POV
(cd "$work" && "$work/prefix/bin/raytrace" gradient.pov +W8 +H8 --passes 1 -o gradient.png \
  > /dev/null)
cat > "$work/mapped.pov" <<'POV'
#version 3.7;
camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }
plane { z, 0 pigment { image_map { png "gradient.png" } }
  finish { emission 1 ambient 0 diffuse 0 } }
POV
(cd "$work" && "$work/prefix/bin/raytrace" mapped.pov +W8 +H8 --passes 1 -o mapped.png \
  > /dev/null)
reader=$work/scene-reader
mkdir -p "$reader"
cat > "$reader/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.22)
project(rayset_scene_reader LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
find_package(rayset CONFIG REQUIRED)
add_executable(scene_reader scene_reader.cpp)
target_link_libraries(scene_reader PRIVATE rayset::scene_language)
CMAKE
cat > "$reader/scene_reader.cpp" <<'CPP'
#include <cstdio>
#include "tracer/scene_language/scene_language.h"
int main(int argc, char** argv) {
    const auto scene = rayset::tracer::parse_scene_file(argv[1]);
    std::printf("%s: %zu objects, %zu files read\n", argv[1], scene.objects.size(),
                scene.files.size());
}
CPP
cmake -S "$reader" -B "$reader/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/reader-configure.log"
cmake --build "$reader/build" > "$work/reader-build.log"
"$reader/build/scene_reader" "$work/mapped.pov"
for program in "$work/prefix/bin/raytrace" "$reader/build/scene_reader"; do
  if ldd "$program" | grep -q libOpenImageIO; then
    echo "$program loads OpenImageIO at start: it belongs in the image reader module" >&2
    exit 1
  fi
done
"$work/prefix/bin/rayconv" synth disk radius=1 flux=1 --rays 200000 --seed 5 -o "$work/disk.tm25ray" > /dev/null
"$work/prefix/bin/raymodel" build "$work/disk.tm25ray" -o "$work/disk.vdb" > /dev/null
"$work/consumer/consumer" "$work/disk.vdb" 200000 | tee "$work/consumer.txt"
awk '
  /^flux / { flux = $2 }
  /^photon mean / { mean = $3; error = $5 }
  /^irradiance / { irradiance = $5 }
  END {
    expected = 1 / (3.14159265358979 * (100 * 100 + 1))
    bad = 0
    if (flux < 1 - 1e-5 || flux > 1 + 1e-5) { print "flux " flux " is not 1 W"; bad = 1 }
    off = mean > flux ? mean - flux : flux - mean
    if (off > 4 * error + 1e-6 * flux) { print "photon mean " mean " +- " error " off"; bad = 1 }
    if (irradiance < 0.98 * expected || irradiance > 1.02 * expected) {
      print "irradiance " irradiance " against " expected; bad = 1 }
    exit bad
  }' "$work/consumer.txt"
