#!/usr/bin/env bash
# Two seamless_snap programs timed on one map in one run, in alternating processes (old, new, old, new, ...):
# per round the wall time, the CPU time (user + sys) and the peak RSS of each whole process (GNU time), and the
# report's snap time (total_ms) and extract phase (extract_ms); then the medians and the median of the per-round
# ratios old / new. Alternation and medians are for a shared machine, where other processes slow both alike.
#
#   benchmark/compare_cli_timing.sh OLD_SEAMLESS_SNAP NEW_SEAMLESS_SNAP MAP.obj [ROUNDS (5)] [-- CLI ARGS (--weld)]
#
# Both outputs must be byte-identical (the script stops otherwise).
set -euo pipefail
old="$1"; new="$2"; map="$3"; shift 3
rounds=5
if [ $# -gt 0 ] && [ "$1" != "--" ]; then rounds="$1"; shift; fi
args=(--weld)
if [ $# -gt 0 ] && [ "$1" = "--" ]; then shift; args=("$@"); fi
command -v /usr/bin/time >/dev/null || { echo "compare_cli_timing: needs GNU time (/usr/bin/time; Debian: time)"; exit 2; }
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }
: > "$tmp/rows"
for r in $(seq 1 "$rounds"); do
  for which in old new; do
    exe="$old"; [ "$which" = new ] && exe="$new"
    /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$exe" "$map" "$tmp/$which.obj" "${args[@]}" --quiet --report "$tmp/$which.json"
    read -r wall user sys kb < "$tmp/time"
    echo "$r $which $wall $(python3 -c "print($user + $sys)") $kb $(field "$tmp/$which.json" total_ms) $(field "$tmp/$which.json" extract_ms)" >> "$tmp/rows"
  done
  cmp -s "$tmp/old.obj" "$tmp/new.obj" || { echo "compare_cli_timing: the outputs differ"; exit 1; }
done
python3 - "$tmp/rows" "$map" <<'EOF'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
faces = None
print("round program  wall_s  cpu_s  peak_MB  snap_ms  extract_ms")
for r in rows:
    print("%5s %-7s %7.2f %6.2f %8.1f %8.1f %11.1f" % (r[0], r[1], float(r[2]), float(r[3]), int(r[4]) / 1024, float(r[5]), float(r[6])))
cols = {"wall s": 2, "cpu s": 3, "peak MB": 4, "snap ms": 5, "extract ms": 6}
print("\n%-11s %10s %10s %16s" % ("median", "old", "new", "old/new (range)"))
for name, c in cols.items():
    o = [float(r[c]) for r in rows if r[1] == "old"]
    n = [float(r[c]) for r in rows if r[1] == "new"]
    if name == "peak MB": o = [x / 1024 for x in o]; n = [x / 1024 for x in n]
    ratios = [a / b for a, b in zip(o, n) if b > 0]
    print("%-11s %10.2f %10.2f %7.2f (%.2f-%.2f)" % (name, statistics.median(o), statistics.median(n), statistics.median(ratios),
                                                     min(ratios), max(ratios)))
print("\n%d rounds on %s, alternating processes; outputs byte-identical in every round" % (len(rows) // 2, sys.argv[2]))
EOF
