#!/usr/bin/env bash
# The test command (CI runs it via .ci/run): installs the dependencies, builds, and runs every test
# with one CTest run over three build directories, so that CTest's closing summary covers them all:
#   $build        Release build (scripts/build.sh): tests compilation_of__*, execution___of__*, package_consumer
#   $build/asan   the test executables with AddressSanitizer + UndefinedBehaviorSanitizer
#                 (-DSEAMLESS_SNAPPING_SANITIZE=ON, -O0 -g1, with clang++ when it has the sanitizer runtimes: it
#                 compiles these CGAL tests in half the time of g++; the Release build stays g++; tests in their
#                 --sanitizer-subset): sanitized__*
#   $build/fuzz   the libFuzzer targets of test/fuzz (clang++, -DSEAMLESS_SNAPPING_FUZZ=ON), each run
#                 on 10000 inputs with a fixed seed from generated seeds: fuzz__* (skipped with a notice without clang/libFuzzer)
# Environment: SEAMLESS_SNAPPING_BUILD_DIR (default <repo>/build); SEAMLESS_SNAPPING_BUILD_BENCHMARKS=ON also builds
# benchmark/ (off here: tables, not tests; scripts/build.sh builds them); SEAMLESS_SNAPPING_CHECKS=0 leaves
# out the sanitizer and fuzz builds (a quick local run). Any failure makes the script exit non-zero.
set -euo pipefail
SECONDS=0
phase() { echo "test: [$((SECONDS / 60))m$((SECONDS % 60))s] $*"; }   # elapsed time in the CI log
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
phase "Release build"
SEAMLESS_SNAPPING_BUILD_BENCHMARKS="${SEAMLESS_SNAPPING_BUILD_BENCHMARKS:-OFF}" bash "$root/scripts/build.sh"
build="${SEAMLESS_SNAPPING_BUILD_DIR:-$root/build}"
build="$(cd "$build" && pwd)"
jobs="$(nproc)"
dirs=("$build")

if [ "${SEAMLESS_SNAPPING_CHECKS:-1}" != 0 ]; then
  # clang++ with libFuzzer and the sanitizer runtimes (Debian: clang libclang-rt-14-dev): the fuzz build needs it,
  # and the sanitizer build uses it when present
  probe="$build/libfuzzer_probe"
  mkdir -p "$probe"
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/probe.cpp"
  clang=0
  if command -v clang++ >/dev/null 2>&1 &&
     clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" >/dev/null 2>&1; then
    clang=1
  fi

  phase "sanitizer build in $build/asan"
  asan_compiler=()
  if [ "$clang" = 1 ]; then asan_compiler=(-DCMAKE_CXX_COMPILER=clang++); fi
  cmake -S "$root" -B "$build/asan" -DCMAKE_BUILD_TYPE=Release -DSEAMLESS_SNAPPING_SANITIZE=ON "${asan_compiler[@]}" >/dev/null
  cmake --build "$build/asan" -j "$jobs"
  dirs+=("$build/asan")

  if [ "$clang" = 1 ]; then
    phase "fuzz build in $build/fuzz"
    cmake -S "$root" -B "$build/fuzz" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
          -DSEAMLESS_SNAPPING_FUZZ=ON >/dev/null
    cmake --build "$build/fuzz" -j "$jobs"
    dirs+=("$build/fuzz")
  else
    echo "test: NOTICE: no clang++ with libFuzzer (Debian: clang libclang-rt-14-dev): the fuzz tests are not run"
  fi
fi

# One CTest run over all build directories (CTest's subdirs() takes absolute paths).
all="$build/all_tests"
mkdir -p "$all"
: > "$all/CTestTestfile.cmake"
for d in "${dirs[@]}"; do echo "subdirs(\"$d\")" >> "$all/CTestTestfile.cmake"; done
phase "tests"
status=0
ctest --test-dir "$all" --output-on-failure -j "$jobs" || status=$?
phase "done (ctest exit $status)"
exit "$status"
