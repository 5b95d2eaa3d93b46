#!/usr/bin/env bash
# Builds everything and runs every test (the Python module's with pytest), then builds the
# converters and the scene language (the parsers of untrusted files) with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs their tests again, and last fuzzes their readers for a
# little while (scripts/fuzz.sh).
# Usage: scripts/test.sh        (installs missing Debian packages first)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

jobs=$(nproc)
# The Python module (python/) is built for the virtual environment install-deps.sh made.
python="$PWD/build/venv/bin/python"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE="$python"
cmake --build build -j "$jobs"
# VTK tests need an X server: xvfb-run gives them one on machines without a display.
xvfb-run -a ctest --test-dir build --output-on-failure -j "$jobs"

# The Python module installed as users install it (pip install .): scikit-build-core builds in
# the same folder (pyproject.toml), where the module is already compiled, so pip only configures
# and packs it (5 s); pytest takes about a minute, and the module about 1.5 minutes of the build
# above on two cores.
"$python" -m pip install -q --disable-pip-version-check --no-build-isolation --no-deps .
"$python" -m pytest -q python/tests

# -O1 -g1: half the compile time of RelWithDebInfo's -O2 -g under the sanitizers, and reports
# still name the function and line.
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DRAYSET_CONVERTERS_ONLY=ON -DRAYSET_SANITIZE=ON
cmake --build build-sanitize -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs"

# A short run of every fuzzing harness (clang, libFuzzer; fuzz/README.md), then every input that
# once crashed a reader replayed through its harness. About seven minutes on two cores, most of
# it the build.
scripts/fuzz.sh 10
ctest --test-dir build-fuzz -L fuzz --output-on-failure -j "$jobs"
