#!/usr/bin/env bash
# Times the exact projection core of this working tree against the core of another revision, in one run:
# core_timing.cpp is built twice with the same flags (against this tree's headers and against REV's,
# taken with git archive), and the two programs run in alternating processes, ROUNDS times per system,
# on the generated seamless-like systems (chain and shuffled order, 2k to 1M rows), random systems, and
# the per-corner seam systems of Directional's dragon when ../shared/data is there (paper mode, both).
# Per system it prints the medians over the rounds of each process's fastest initialize + project and
# the median of the per-round ratios REV / this tree (> 1: this tree is faster), with their range, and
# whether both gave the same x (hash; not where the revisions choose other pivots, e.g. the dragon before
# and after the fill-reducing orders: another exact solution). Shared virtual machines drift by several percent from minute to
# minute; the ratios of alternating processes are what to read.
#
#   bash benchmark/compare_core_revisions.sh REV [ROUNDS] [--quick]     e.g. d725e6e (before the fill-reducing orders)
#
# Needs g++, python3, CGAL, Eigen and GMP/MPFR as installed by scripts/install_deps.sh; SuiteSparse COLAMD
# is used for both builds when present (a revision that does not know it ignores it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rev="${1:?usage: compare_core_revisions.sh REV [ROUNDS] [--quick]}"
rounds="${2:-7}"
quick=0; [ "${3:-}" = "--quick" ] && quick=1
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
mkdir -p "$work/rev"
git -C "$root" archive "$rev" include | tar -x -C "$work/rev"
flags=(-std=c++17 -O3 -DNDEBUG -DCGAL_NDEBUG -DCGAL_EIGEN3_ENABLED -frounding-math -ffp-contract=off -isystem /usr/include/eigen3)
libs=(-lgmpxx -lmpfr -lgmp)
if [ -f /usr/include/suitesparse/colamd.h ]; then
  flags+=(-DCGAL_SEAMLESS_SNAPPING_HAS_COLAMD -isystem /usr/include/suitesparse); libs+=(-lcolamd)
fi
echo "building core_timing against $rev and against this tree ..."
g++ "${flags[@]}" -I"$work/rev/include" "$root/benchmark/core_timing.cpp" -o "$work/core_rev" "${libs[@]}" &
g++ "${flags[@]}" -I"$root/include" "$root/benchmark/core_timing.cpp" -o "$work/core_now" "${libs[@]}"
wait
systems=("seamless 2000 1 0 50" "seamless 2000 1 1 50" "seamless 20000 2 0 20" "seamless 20000 2 1 20" "random 1000 5 10")
if [ "$quick" = 0 ]; then
  systems+=("seamless 100000 3 0 5" "seamless 100000 3 1 5" "seamless 1000000 4 0 2" "seamless 1000000 4 1 2" "random 2000 6 3")
fi
data="$root/../shared/data/directional"
if [ -d "$data" ]; then
  cmake -S "$root" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DSEAMLESS_SNAPPING_BUILD_EXAMPLES=OFF \
        -DSEAMLESS_SNAPPING_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$work/build" --target bench_projection >/dev/null
  "$work/build/benchmark/bench_projection" --real "$data/dragon-param-full-seamless.obj" --real "$data/dragon-param-rot-seamless.obj" \
      --repeat 1 --no-check --write-dir "$work" >/dev/null
  for f in dragon-param-full-seamless dragon-param-rot-seamless; do systems+=("mtx $work/$f.mtx $work/${f}_xbar.txt 20"); done
fi
printf '%-44s %12s %12s %8s %15s %s\n' "system ($rounds alternating rounds)" "$rev ms" "now ms" "ratio" "range" "same x"
for sys in "${systems[@]}"; do
  for ((r = 0; r < rounds; ++r)); do
    echo "rev $("$work/core_rev" $sys)"
    echo "now $("$work/core_now" $sys)"
  done | python3 -c '
import re, statistics, sys
runs = {"rev": [], "now": []}
for line in sys.stdin:
    m = re.search(r"total_min ([\d.]+) .* hash (\w+)", line)
    runs[line.split()[0]].append((float(m.group(1)), m.group(2)))
ratios = [a[0] / b[0] for a, b in zip(runs["rev"], runs["now"])]
words = sys.argv[1].split()
name = words[1].rsplit("/", 1)[-1][:-4] if words[0] == "mtx" else sys.argv[1]
print("%-44s %12.3f %12.3f %8.3f %7.3f-%.3f %s" % (name, statistics.median(t for t, _ in runs["rev"]),
      statistics.median(t for t, _ in runs["now"]), statistics.median(ratios), min(ratios), max(ratios),
      "yes" if runs["rev"][0][1] == runs["now"][0][1] else "no"))
' "$sys"
done
