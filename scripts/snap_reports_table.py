#!/usr/bin/env python3
"""The JSON reports of many `seamless_snap ... --report FILE.json` runs merged into one Markdown table.

    python3 scripts/snap_reports_table.py out/*.json > summary.md

One row per report (sorted by input name): input, status, faces, cones, nodes, negative UV triangles at the end,
the largest change relative to the UV diagonal, the snap's time (total_ms), the extract phase per face; then a
line with the counts. Exit status 1 if a report is missing, unreadable or not SUCCESS, so that a batch script can
test it. Standard library only.
"""
import json
import sys


def main(paths):
    if not paths:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    rows, bad = [], 0
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                r = json.load(f)
        except (OSError, ValueError) as e:
            rows.append((path, "UNREADABLE", "", "", "", "", "", "", "", str(e)))
            bad += 1
            continue
        status = r.get("status", "?")
        bad += status != "SUCCESS"
        faces = r.get("faces", 0)
        rows.append((r.get("input", path), status, faces, r.get("cones", ""), r.get("nodes", ""),
                     r.get("flips_after_repair", ""), "%.2e" % r.get("max_change", 0), "%.1f" % r.get("total_ms", 0),
                     "%.3f" % (1000.0 * r.get("extract_ms", 0) / faces) if faces else "",
                     "" if status == "SUCCESS" else r.get("message", "")[:200]))
    rows.sort(key=lambda row: str(row[0]))
    print("| input | status | faces | cones | nodes | negative UV triangles | max change / diagonal | snap ms "
          "| extract us/face | message |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for row in rows:
        print("| " + " | ".join(str(c).replace("|", "/") for c in row) + " |")
    print("\n%d of %d reports are SUCCESS" % (len(rows) - bad, len(rows)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
