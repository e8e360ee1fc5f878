#!/usr/bin/env bash
# Configures and builds the package in ./build (Release). Used by test.sh and demo.sh.
# SEAMLESS_SNAPPING_BUILD_BENCHMARKS=OFF leaves out benchmark/ (test.sh does: the benchmarks are tables, not tests,
# and their four CGAL translation units cost the test run about 2-3 minutes); default ON.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install_deps.sh"
build="${SEAMLESS_SNAPPING_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DSEAMLESS_SNAPPING_BUILD_BENCHMARKS="${SEAMLESS_SNAPPING_BUILD_BENCHMARKS:-ON}" >/dev/null
cmake --build "$build" -j "$(nproc)" "$@"
