"""CTest test of the seamless_snap command line: automatic welding of a cut mesh (the same output bits with the
default heap, SEAMLESS_SNAPPING_HEAP=default, as with the retained heap of the program's restart), --no-weld refusing an
input whose seams are invisible, --keep-layout, --fail-on-new-flips, the JSON report's keys, --pin, --outdir with
--summary (several inputs), and --integer-grid --vval (libQEx's vertex valence file; IN.obj is CGAL's Orbifold Tutte square map of a
closed genus-0 mesh, which is near an integer-grid map).
usage: python3 cli_test.py SEAMLESS_SNAP IN.obj WORKDIR   (IN.obj: an approximately seamless map)
IN.obj is computed at test time (CGAL's solver: its last bits depend on the CPU), so nothing here is compared with stored
values; the bit-for-bit checks compare the program's output with its own input (kept positions, pinned UVs that are
exact binary fractions), the same on every machine."""
import json
from fractions import Fraction
import os
import shutil
import subprocess
import sys
import threading

from cut_mesh import write_cut_mesh
from fold_over_grid import write_fold_over_grid

exe, src, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)   # no file of an earlier run may pass a 'nothing written' check
os.makedirs(work, exist_ok=True)


def run(*args, env=None):
    p = subprocess.run([exe, *args], capture_output=True, text=True, env=env)
    return p.returncode, p.stdout + p.stderr


def records(path, kind):
    with open(path) as f:
        return [l.split()[1:] for l in f if l.split() and l.split()[0] == kind]


# a cut mesh made from the input: one 'v' per 'vt' (vertices duplicated along the seams), as libigl/Directional write
cut = os.path.join(work, "cut.obj")
write_cut_mesh(src, cut)
pos, vt, faces = records(cut, "v"), records(cut, "vt"), records(src, "f")

failures = []
checks = [0]
def check(cond, what):
    checks[0] += 1
    if not cond:
        failures.append(what)

# 1. automatic weld: the seams are found and snapped
out1, rep1 = os.path.join(work, "welded.obj"), os.path.join(work, "welded.json")
rc, text = run(cut, out1, "--report", rep1)
check(rc == 0 and "welded automatically" in text, "cut mesh: automatic weld, exit 0: %d %s" % (rc, text))
r = json.load(open(rep1))
check(r["status"] == "SUCCESS" and r["cut_edges"] > 0, "cut mesh: seams seen after welding")
check(r["input"] == cut and r["output"] == out1 and r["version"], "JSON report names input, output, version")

# 1a. a cut mesh with a hole at a seam: read as it is, a vertex there has two fans of faces (non-manifold), so the
# automatic weld cannot wait for the cut-mesh test; welded it is a valid mesh with a border, and it snaps
cut_lines = open(cut).read().split("\n")
cut_faces = [i for i, l in enumerate(cut_lines) if l.startswith("f ")]
corners = [[int(c.split("/")[0]) for c in cut_lines[i].split()[1:]] for i in cut_faces]
edge_count = {}
for f in corners:
    for a, b in zip(f, f[1:] + f[:1]):
        edge_count[frozenset((a, b))] = edge_count.get(frozenset((a, b)), 0) + 1
border_vertex = set(v for e, n in edge_count.items() if n == 1 for v in e)
# a face at a border vertex (a seam side) none of whose edges is on the border: removing it splits that vertex's fan
hole = next(i for i, f in zip(cut_faces, corners)
            if any(v in border_vertex for v in f) and all(edge_count[frozenset((a, b))] == 2 for a, b in zip(f, f[1:] + f[:1])))
holed = os.path.join(work, "cut_hole.obj")
open(holed, "w").write("\n".join(l for i, l in enumerate(cut_lines) if i != hole))
rc, text = run(holed, os.path.join(work, "cut_hole_out.obj"))
check(rc == 0 and "welded automatically: read as it is, the input is refused" in text and "non-manifold" in text,
      "cut mesh with a hole at a seam: welded automatically, exit 0: %d %s" % (rc, text))
rc, text = run(holed, os.path.join(work, "cut_hole_no_weld.obj"), "--no-weld")
check(rc == 1 and "non-manifold" in text, "the same with --no-weld: refused as it reads: %d %s" % (rc, text))

# 1b. the heap (the retained heap after the program's restart on glibc, or the default heap) does not change the output bits
out1b = os.path.join(work, "welded_default_heap.obj")
rc, text = run(cut, out1b, env=dict(os.environ, SEAMLESS_SNAPPING_HEAP="default"))
check(rc == 0 and open(out1b, "rb").read() == open(out1, "rb").read(),
      "SEAMLESS_SNAPPING_HEAP=default: the same output bits as with the retained heap: %d %s" % (rc, text))

# 2. --no-weld: no seam is visible; an error, not 'already exactly seamless'
out2 = os.path.join(work, "noweld.obj")
rc, text = run(cut, out2, "--no-weld")
check(rc == 1 and "no seam is visible" in text and not os.path.exists(out2), "--no-weld on a cut mesh: %d %s" % (rc, text))

# 3. --keep-layout: the same v and vt lines in number and order, the same faces; only UVs move
out3 = os.path.join(work, "layout.obj")
rc, text = run(cut, out3, "--keep-layout")
check(rc == 0, "--keep-layout: exit %d %s" % (rc, text))
if rc == 0:
    v3, vt3, f3 = records(out3, "v"), records(out3, "vt"), records(out3, "f")
    check(len(v3) == len(pos) and len(vt3) == len(vt), "--keep-layout: v/vt counts kept")
    check(all(float(a) == float(b) for p, q in zip(pos, v3) for a, b in zip(p, q)), "--keep-layout: positions kept")
    check([[c.split("/")[:2] for c in f] for f in f3] == [[[c.split("/")[1]] * 2 for c in f] for f in faces],
          "--keep-layout: face indices kept")
    moved = sum(1 for a, b in zip(vt, vt3) if [float(x) for x in a] != [float(x) for x in b])
    check(0 < moved < len(vt), "--keep-layout: some UVs moved (%d of %d)" % (moved, len(vt)))
    rc, text = run(out3, os.path.join(work, "again.obj"), "--keep-layout")
    check(rc == 0 and "already exactly seamless" in text, "the result is exactly seamless: %s" % text)

# 4. --integer-grid --vval: the VVAL file (header line, vertex count = the v lines of OUT.obj, one valence per
# vertex); the cones of the field are exactly the vertices whose valence is not 4, and on a closed genus-0 surface
# the valences satisfy Gauss-Bonnet exactly: sum (4 - valence) = 4 chi = 8. On the bear's Parallelogram map (4 cones
# of 180 degrees, valence 2; grid scale 4, as seamless_quad's example); the Square map's cones of 90 degrees have
# valence 1, which no quad mesh has: refused, nothing written
square_out, square_vval = os.path.join(work, "square.obj"), os.path.join(work, "square.vval")
rc, text = run(src, square_out, "--integer-grid", "--vval", square_vval)
check(rc == 1 and "(a cone of valence 1)" in text and not os.path.exists(square_out) and not os.path.exists(square_vval),
      "--vval with cones of 90 degrees: exit 1, nothing written: %d %s" % (rc, text))
parallelogram = os.path.join(os.path.dirname(src), "bear_parallelogram.obj")
out5, vval5, rep5 = os.path.join(work, "igm.obj"), os.path.join(work, "igm.vval"), os.path.join(work, "igm.json")
rc, text = run(parallelogram, out5, "--integer-grid", "--grid-scale", "4", "--vval", vval5, "--report", rep5)
check(rc == 0 and "VVAL" in text, "--integer-grid --vval: exit %d %s" % (rc, text))
if rc == 0:
    lines = open(vval5).read().split("\n")
    check(lines[0] == '{"file_format":"VVAL","version":1}', "VVAL header: %r" % lines[0])
    values = [int(x) for x in " ".join(lines[2:]).split()]
    check(int(lines[1]) == len(values) == len(records(out5, "v")), "VVAL count = vertices of OUT.obj")
    r5 = json.load(open(rep5))
    check(sum(1 for x in values if x != 4) == r5["field_cones"] > 0,
          "valences other than 4 = the field cones (%d)" % r5["field_cones"])
    check(sum(4 - x for x in values) == 8, "Gauss-Bonnet: sum(4 - valence) = %d, not 8" % sum(4 - x for x in values))
# --vval needs --integer-grid (exit 2); a refused integer-grid snap writes neither OUT.obj nor the VVAL file
rc, text = run(src, os.path.join(work, "x.obj"), "--vval", os.path.join(work, "x.vval"))
check(rc == 2 and "--vval needs --integer-grid" in text, "--vval without --integer-grid: %d %s" % (rc, text))
far = os.path.join(work, "scaled.obj")
with open(src) as f, open(far, "w") as o:
    for l in f:
        p = l.split()
        o.write("vt %r %r\n" % (0.3 * float(p[1]), 0.3 * float(p[2])) if p and p[0] == "vt" else l)
out6, vval6 = os.path.join(work, "far.obj"), os.path.join(work, "far.vval")
rc, text = run(far, out6, "--integer-grid", "--vval", vval6)
check(rc == 1 and not os.path.exists(out6) and not os.path.exists(vval6),
      "--vval on a map that is not near an IGM: exit 1, nothing written: %d %s" % (rc, text))
check("after snapping" not in text and "max change" not in text,
      "a refused snap prints no change and no counts after snapping (nothing was snapped): %s" % text)

# --vval next to fold-overs (kept with --no-untangle): refused (FOLD_OVERS, the faces listed), neither OUT.obj nor
# the VVAL file written
folds = os.path.join(work, "folds.obj")
write_fold_over_grid(folds)
out9, vval9 = os.path.join(work, "folds_out.obj"), os.path.join(work, "folds.vval")
rc, text = run(folds, out9, "--integer-grid", "--no-untangle", "--vval", vval9)
check(rc == 1 and "FOLD_OVERS" in text and "fold-overs" in text and not os.path.exists(out9) and not os.path.exists(vval9),
      "--vval next to fold-overs: exit 1, nothing written: %d %s" % (rc, text))
# the same map with --integer-grid's default untangling: the fold-overs are removed, OUT.obj has every UV triangle
# positive (checked here on the written doubles, exactly: integer coordinates after the snap) and the VVAL file
# gives every vertex a valence
out9, vval9, report9 = os.path.join(work, "folds_untangled.obj"), os.path.join(work, "folds_untangled.vval"), os.path.join(work, "folds.json")
for f in (out9, vval9, report9):
    if os.path.exists(f): os.remove(f)
rc, text = run(folds, out9, "--integer-grid", "--vval", vval9, "--report", report9)
r9 = json.load(open(report9)) if os.path.exists(report9) else {}
check(rc == 0 and r9.get("flips_before") == 2 and r9.get("flips_after_repair") == 0 and
      r9.get("degenerate_after_repair") == 0 and os.path.exists(vval9),
      "--integer-grid untangles the fold-over grid: %d %s" % (rc, text))
if rc == 0:
    vts, tris = [], []
    for l in open(out9):
        p = l.split()
        if p and p[0] == "vt": vts.append((Fraction(p[1]), Fraction(p[2])))
        if p and p[0] == "f": tris.append([int(c.split("/")[1]) - 1 for c in p[1:]])
    def area2(t):
        (a, b), (c, d), (e, f) = vts[t[0]], vts[t[1]], vts[t[2]]
        return (c - a) * (f - b) - (d - b) * (e - a)
    check(len(tris) == 18 and all(area2(t) > 0 for t in tris), "untangled fold-over grid: every UV triangle positive (exact)")

# 6. --pin FILE: a seam vertex whose two sectors' UVs are rounded to multiples of 2^-20 (on the snap's grid) keeps
# them bit for bit; a vertex with generic UVs (bits below the grid quantum) is refused, nothing written
corners = {}
for f in faces:
    for c in f:
        a, b = (int(x) for x in c.split("/")[:2])
        corners.setdefault(a - 1, set()).add(b - 1)
uvs_of = lambda v: set(tuple(vt[t]) for t in corners[v])
seam_v = next(v for v in sorted(corners) if len(uvs_of(v)) == 2)
rounded = dict((t, ["%r" % (round(float(x) * 2 ** 20) / 2 ** 20) for x in vt[t]]) for t in corners[seam_v])
pinned_in = os.path.join(work, "pinned_in.obj")
with open(src) as f, open(pinned_in, "w") as o:
    k = 0
    for l in f:
        p = l.split()
        if p and p[0] == "vt":
            o.write("vt %s\n" % " ".join(rounded[k]) if k in rounded else l)
            k += 1
        else:
            o.write(l)
pin_file = os.path.join(work, "pin.txt")
with open(pin_file, "w") as o:
    o.write("# the seam vertex\n%d\n" % seam_v)
out7 = os.path.join(work, "pinned.obj")
rc, text = run(pinned_in, out7, "--pin", pin_file)
check(rc == 0 and "1 pinned vertices" in text, "--pin: exit %d %s" % (rc, text))
if rc == 0:
    vt7, f7 = records(out7, "vt"), records(out7, "f")
    got = set(tuple(float(x) for x in vt7[int(c.split("/")[1]) - 1]) for f in f7 for c in f
              if int(c.split("/")[0]) - 1 == seam_v)
    want = set(tuple(float(x) for x in r) for r in rounded.values())
    check(got == want, "--pin: the pinned vertex keeps its UVs bit for bit: %s vs %s" % (got, want))
# bits below 2^-50 (the |UV| are below 2, so the grid quantum 2^(K-52) is at most 2^-50)
generic = next(v for v in sorted(corners) if v != seam_v and any(float(x) * 2 ** 50 != int(float(x) * 2 ** 50)
                                                                  for uv in uvs_of(v) for x in uv))
with open(pin_file, "w") as o:
    o.write("%d\n" % generic)
out8 = os.path.join(work, "pinned_bad.obj")
rc, text = run(pinned_in, out8, "--pin", pin_file)
check(rc == 1 and "pinned corner (vertex %d" % generic in text and not os.path.exists(out8),
      "--pin of a UV below the grid quantum: %d %s" % (rc, text))
with open(pin_file, "w") as o:
    o.write("%d 1\n" % generic)
rc, text = run(pinned_in, out8, "--pin", pin_file)
check(rc == 1 and "pin.txt:1: expected one vertex index" in text, "--pin: malformed line: %d %s" % (rc, text))
with open(pin_file, "w") as o:       # beyond long long: refused, not skipped as a blank line
    o.write("# pinned\n99999999999999999999999\n")
rc, text = run(pinned_in, out8, "--pin", pin_file)
check(rc == 1 and "pin.txt:2: '99999999999999999999999' is not a vertex index" in text and not os.path.exists(out8),
      "--pin: index beyond long long: %d %s" % (rc, text))

# 5. --fail-on-new-flips passes when nothing flips, --help lists every option
rc, text = run(src, os.path.join(work, "flips.obj"), "--fail-on-new-flips")
check(rc == 0, "--fail-on-new-flips on a map without introduced flips: %d %s" % (rc, text))
rc, text = run("--help")
for opt in ["--weld", "--no-weld", "--keep-layout", "--fail-on-new-flips", "--no-align-boundary", "--unreduced",
            "--pin", "--vval", "--report", "--outdir", "--summary", "--merge-cone-pairs", "--quantize", "--quiet", "--help"]:
    check(opt in text, "--help lists " + opt)
rc, text = run(src, os.path.join(work, "merge.obj"), "--merge-cone-pairs")
check(rc == 2 and "--integer-grid" in text, "--merge-cone-pairs without --integer-grid: exit 2: %d %s" % (rc, text))
rc, text = run(src, os.path.join(work, "quantize.obj"), "--quantize")
check(rc == 2 and "--integer-grid" in text, "--quantize without --integer-grid: exit 2: %d %s" % (rc, text))

# 6. --outdir: several inputs (the map and the cut mesh), each as a single run would write it, a report per input
#    and the summary table; a missing input makes the exit status 1 without stopping the others
outdir, summary = os.path.join(work, "batch"), os.path.join(work, "batch_summary.md")
missing = os.path.join(work, "missing.obj")
rc, text = run("--quiet", "--outdir", outdir, src, cut, missing, "--summary", summary)
check(rc == 1, "--outdir with a missing input: exit 1: %d %s" % (rc, text))
name = os.path.splitext(os.path.basename(src))[0]
single = os.path.join(work, "single.obj")
run(src, single, "--quiet")
with open(single, "rb") as a, open(os.path.join(outdir, name + ".obj"), "rb") as b:
    check(a.read() == b.read(), "--outdir writes what a single run writes")
check(json.load(open(os.path.join(outdir, name + ".json")))["status"] == "SUCCESS", "--outdir: a report per input")
check(json.load(open(os.path.join(outdir, "cut.json")))["status"] == "SUCCESS", "--outdir: the cut mesh welded automatically")
table = open(summary).read()
check("2 of 3 inputs snapped exactly" in table and "| FAILED |" in table and "missing.obj" in table,
      "--summary: the table names every input and status: %s" % table)
# a '|' in a file name (and so in the message naming it) is escaped in the table: every row keeps its 11 cells
import re
piped_summary = os.path.join(work, "piped_summary.md")
rc, text = run("--quiet", "--outdir", os.path.join(work, "piped"), os.path.join(work, "a|b.obj"), "--summary", piped_summary)
rows = [l for l in open(piped_summary).read().splitlines() if l.startswith("| ")]
check(rc == 1 and len(rows) == 2 and all(len(re.findall(r"(?<!\\)\|", l)) == 12 for l in rows) and "a\\|b.obj" in rows[1],
      "--summary escapes '|': %s" % rows)
# an input that cannot be read gets its report too (status INVALID_INPUT, the reader's message), as with --report
missing_report = json.load(open(os.path.join(outdir, "missing.json")))
check(missing_report["status"] == "INVALID_INPUT" and "cannot read input" in missing_report["message"] and
      missing_report["input"] == missing, "--outdir: a report for the unreadable input: %s" % missing_report)
rc, text = run(missing, os.path.join(work, "m.obj"), "--report", os.path.join(work, "missing_single.json"))
check(rc == 1 and json.load(open(os.path.join(work, "missing_single.json")))["status"] == "INVALID_INPUT",
      "--report of an unreadable input: exit 1, the report written: %d %s" % (rc, text))
# two inputs with one file name would overwrite each other's results: refused (exit 2), nothing written
os.makedirs(os.path.join(work, "other"), exist_ok=True)
twin = os.path.join(work, "other", os.path.basename(src))
shutil.copyfile(src, twin)
rc, text = run("--outdir", os.path.join(work, "twins"), src, twin)
check(rc == 2 and "name one file" in text and not os.path.exists(os.path.join(work, "twins")),
      "--outdir with two inputs of one name: exit 2, nothing written: %d %s" % (rc, text))
# --summary naming the report of an input: refused too
stem = os.path.splitext(os.path.basename(src))[0]
rc, text = run("--outdir", os.path.join(work, "twins"), src, "--summary", os.path.join(work, "twins", stem + ".json"))
check(rc == 2 and "name one file" in text and not os.path.exists(os.path.join(work, "twins")),
      "--outdir with --summary on a report: exit 2, nothing written: %d %s" % (rc, text))
# --summary naming an input replaced that map with the table (exit 0): refused, the input unchanged; an empty
# --outdir (an unset shell variable) switched to a single run that wrote over the second input: refused
victim = os.path.join(work, "victim.obj")
shutil.copyfile(src, victim)
victim_bytes = open(victim, "rb").read()
for args in [("--outdir", os.path.join(work, "victims"), victim, "--summary", victim),
             ("--outdir", os.path.join(work, "victims"), src, victim, "--summary", victim),
             ("--outdir", "", src, victim), ("--outdir", os.path.join(work, "victims"), src, "--summary", "")]:
    rc, text = run(*args)
    check(rc == 2 and open(victim, "rb").read() == victim_bytes and not os.path.exists(os.path.join(work, "victims")),
          "%s: exit 2, the input unchanged, nothing written: %d %s" % (args, rc, text))
# --quiet prints nothing but errors (the table went to stdout); a --summary that cannot be written is refused before
# any input is snapped (it was found after all of them)
rc, text = run("--quiet", "--outdir", os.path.join(work, "quiet"), src, "--summary", os.path.join(work, "quiet.md"))
check(rc == 0 and text == "" and os.path.exists(os.path.join(work, "quiet.md")), "--outdir --quiet: silent: %d %r" % (rc, text))
rc, text = run("--outdir", os.path.join(work, "late"), src, "--summary", os.path.join(work, "no_dir", "s.md"))
check(rc == 1 and "--summary" in text and not os.path.exists(os.path.join(work, "late")),
      "--summary in a missing directory: refused before the inputs: %d %s" % (rc, text))
rc, text = run("--quiet", "--outdir", os.path.join(work, "fresh"), src, "--summary", os.path.join(work, "fresh", "s.md"))
check(rc == 0 and os.path.exists(os.path.join(work, "fresh", "s.md")),
      "--summary in the --outdir it creates (README's example): %d %s" % (rc, text))
rc, text = run("--outdir", os.path.join(work, "victims"), victim, "--summary", victim)
check("the input '%s' and --summary name one file" % victim in text, "the clash names the summary as the file that would replace: %s" % text)
# two options naming one output file: the second would replace the first, and the run would still say both were
# written: refused (exit 2), nothing written
clash = os.path.join(work, "clash.obj")
rc, text = run(src, clash, "--report", os.path.join(work, ".", "clash.obj"))
check(rc == 2 and "name one file" in text and not os.path.exists(clash), "OUT = --report: exit 2: %d %s" % (rc, text))
# the same with relative paths to a file not written yet ('x' and './x' compared unequal: the VVAL file replaced OUT)
p = subprocess.run([exe, os.path.abspath(src), "rel.obj", "--integer-grid", "--vval", "./rel.obj"], capture_output=True,
                   text=True, cwd=work)
check(p.returncode == 2 and "name one file" in p.stdout + p.stderr and not os.path.exists(os.path.join(work, "rel.obj")),
      "OUT = ./OUT as --vval, relative, not yet written: exit 2: %d %s" % (p.returncode, p.stdout + p.stderr))
# two squares whose shared side lies at x = 0 in one and x = -0 in the other: not bit-identical, so not a cut mesh (the
# test compared values, the weld bits: "welded automatically" announced, 0 vertices welded)
negzero = os.path.join(work, "negzero.obj")
with open(negzero, "w") as f:
    f.write("v -1 0 0\nv 0 0 0\nv 0 1 0\nv -1 1 0\nv -0 0 0\nv 1 0 0\nv 1 1 0\nv -0 1 0\n"
            "vt -1 0\nvt 0 0\nvt 0 1\nvt -1 1\nvt 0.5 0\nvt 1.5 0\nvt 1.5 1\nvt 0.5 1\n"
            "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/5 6/6 7/7\nf 5/5 7/7 8/8\n")
rc, text = run(negzero, os.path.join(work, "negzero_out.obj"))
check(rc == 0 and "welded automatically" not in text, "-0 and 0 are not one point for the cut-mesh test: %d %s" % (rc, text))
# a file name that is not UTF-8 (a Latin-1 byte): the JSON report stays valid (the byte is read as its Latin-1
# character; raw, it made the report unreadable)
latin = os.path.join(work.encode(), b"lat\xe9.obj")
shutil.copyfile(src, latin)
latin_report = os.path.join(work, "latin.json")
p = subprocess.run([exe.encode(), latin, os.path.join(work, "latin_out.obj").encode(), b"--report", latin_report.encode()],
                   capture_output=True)
try:
    latin_input = json.load(open(latin_report, encoding="utf-8"))["input"]
except ValueError as e:
    latin_input = "unreadable: %s" % e
check(p.returncode == 0 and latin_input.endswith("lat\u00e9.obj"), "a Latin-1 file name in the report: %r" % latin_input)
# a run that fails after the snap succeeded (OUT in a directory that does not exist; a --vval file that cannot be
# written) exits 1, writes no OUT, and its report says so ("status" not SUCCESS, "output" null); the report said
# SUCCESS and named the output, and a failed --vval left OUT written
late = os.path.join(work, "late.json")
rc, text = run(src, os.path.join(work, "no_such_dir", "o.obj"), "--report", late)
r = json.load(open(late))
check(rc == 1 and r["status"] == "INVALID_INPUT" and r["output"] is None and "the snap itself" in r["message"],
      "OUT in a missing directory: exit 1, the report says why: %d %s %s" % (rc, text, r["status"]))
vout = os.path.join(work, "vval_out.obj")
rc, text = run(src, vout, "--integer-grid", "--vval", os.path.join(work, "no_such_dir", "v.vval"), "--report", late)
r = json.load(open(late))
check(rc == 1 and not os.path.exists(vout) and r["status"] != "SUCCESS" and r["output"] is None,
      "--vval in a missing directory: exit 1, no OUT, the report says why: %d %s %s" % (rc, text, r["status"]))
# --quantize with align edges: the cube in the usual cross layout (its edges as features, --sharp-angle 60) scaled by 1.3,
# near no integer-grid map: at grid scale 8 the quantization put the two cones of one aligned edge on different isolines
# (INFEASIBLE, a row of the node system named); now each cone takes a point on the isolines of the chains through it:
# an exact map of a box, fold-free, written
cube = os.path.join(work, "cube13.obj")
with open(cube, "w") as f:
    for x, y, z in [(-1, -1, 1), (1, -1, 1), (-1, 1, 1), (1, 1, 1), (-1, 1, -1), (1, 1, -1), (-1, -1, -1), (1, -1, -1)]:
        f.write("v %g %g %g\n" % (x / 2, y / 2, z / 2))
    for u, v in [(3, 0), (5, 0), (3, 2), (5, 2), (3, 4), (5, 4), (3, 6), (5, 6), (3, 8), (5, 8), (7, 0), (7, 2), (1, 0),
                 (1, 2)]:
        f.write("vt %r %r\n" % (1.3 * u / 8, 1.3 * v / 8))
    for face in ["1/1 2/2 3/3", "3/3 2/2 4/4", "3/3 4/4 5/5", "5/5 4/4 6/6", "5/5 6/6 7/7", "7/7 6/6 8/8", "7/7 8/8 1/9",
                 "1/9 8/8 2/10", "2/2 8/11 4/4", "4/4 8/11 6/12", "7/13 1/1 5/14", "5/14 1/1 3/3"]:
        f.write("f %s\n" % face)
cube_out, cube_report = os.path.join(work, "cube13_snapped.obj"), os.path.join(work, "cube13.json")
rc, text = run(cube, cube_out, "--integer-grid", "--quantize", "--sharp-angle", "60", "--grid-scale", "8", "--report",
               cube_report)
report = json.load(open(cube_report))
check(rc == 0 and report["status"] == "SUCCESS" and report["quantized"] and report["align_edges"] == 12 and
      report["flips_after_repair"] == 0 and report["degenerate_after_repair"] == 0 and os.path.exists(cube_out),
      "--quantize with align edges: an exact box: %d %s" % (rc, text))
# its 8 vertices are cones: each corner on an integer point of the grid at scale 8, exactly
check(all((8 * Fraction(float(c))).denominator == 1 for row in records(cube_out, "vt") for c in row),
      "the quantized box: every corner UV on an integer point at grid scale 8")
rc, text = run(cube, cube_out, "--integer-grid", "--quantize", "--report", cube_report)
check(rc == 0 and json.load(open(cube_report))["status"] == "SUCCESS", "the cube quantized without features: %d %s" % (rc, text))
for bad in ["3", "0", "-1", "nan", "inf"]:   # not a power of two: a command-line error (it was exit 1 from the snap), also without --integer-grid
    rc, text = run(src, os.path.join(work, "bad_scale.obj"), "--grid-scale", bad)
    check(rc == 2 and "power of two" in text and not os.path.exists(os.path.join(work, "bad_scale.obj")),
          "--grid-scale %s: exit 2: %d %s" % (bad, rc, text))
# counts and numbers are read whole: " -1" threads wrapped around to ULLONG_MAX in std::strtoul (then refused only by
# the range), "2x" or an empty value must not read as a prefix
for opt, bad in [("--threads", " -1"), ("--threads", "2x"), ("--threads", ""), ("--threads", "1025"),
                 ("--max-untangle-change", "1 "), ("--sharp-angle", "")]:
    rc, text = run(src, os.path.join(work, "bad_value.obj"), opt, bad)
    check(rc == 2 and not os.path.exists(os.path.join(work, "bad_value.obj")), "%s %r: exit 2: %d %s" % (opt, bad, rc, text))
# a report or VVAL file naming the input: the map was replaced by JSON (exit 0); now exit 2, the input unchanged
copy = os.path.join(work, "input_copy.obj")
shutil.copyfile(src, copy)
before = open(copy, "rb").read()
for args in [["--report", copy], ["--integer-grid", "--vval", copy]]:
    rc, text = run(copy, os.path.join(work, "over_input.obj"), *args)
    check(rc == 2 and "name one file" in text and open(copy, "rb").read() == before,
          "%s naming IN: exit 2, IN unchanged: %d %s" % (args[-2], rc, text))
rc, text = run(src, single, "extra.obj")
check(rc == 2 and "several inputs: --outdir" in text, "a third file name without --outdir: %d %s" % (rc, text))

# 7. reading and writing files (the I/O sweep)
small = cube   # the cube of 1.3, snapped in well under a second

# /dev/stdout (also --report) is written where the shell's `>> log` stands: write_atomically() followed it to the
# regular file log and renamed a temporary file over it (log lost its earlier lines)
# (also under other names: //dev/stdout, a symbolic link to it, which went the regular-file way)
stdout_link = os.path.join(work, "stdout_link.obj")
if os.name == "posix" and not os.path.lexists(stdout_link):
    os.symlink("/dev/stdout", stdout_link)
for args in [["/dev/stdout", "--quiet"], [os.path.join(work, "to_log.obj"), "--quiet", "--report", "/dev/stdout"],
             ["//dev/stdout", "--quiet"], [stdout_link, "--quiet"]]:
    log = os.path.join(work, "log.txt")
    with open(log, "w") as f:
        f.write("an earlier line\n")
    with open(log, "a") as f:
        rc = subprocess.run([exe, small, *args], stdout=f, stderr=subprocess.PIPE).returncode
    text = open(log).read()
    check(rc == 0 and text.startswith("an earlier line\n") and ("\nv " in text if "--report" not in args else '"output"' in text),
          "%s >> log: log keeps its lines and gets the output: %d %r" % (" ".join(args), rc, text[:80]))

# a pipe as input: with 2 threads the reader seeked on it and read it as empty ("empty mesh: no face in 0 lines")
piped = os.path.join(work, "piped.obj")
p = subprocess.run([exe, "/dev/stdin", piped, "--threads", "2"], input=open(small).read(), capture_output=True, text=True)
check(p.returncode == 0 and records(piped, "f") == records(small, "f"),
      "a pipe as input, 2 threads: %d %s" % (p.returncode, p.stdout + p.stderr))
# an input read twice (a cut mesh, welded after a first read; --keep-layout) from a pipe: refused with the reason (the
# second read found the pipe empty); from a FIFO it waited for a writer for ever
for twice, args in [(cut, []), (small, ["--keep-layout"])]:
    for threads in ["1", "2"]:
        piped2 = os.path.join(work, "piped_twice.obj")
        p = subprocess.run([exe, "/dev/stdin", piped2, "--threads", threads, *args], input=open(twice).read(),
                           capture_output=True, text=True)
        check(p.returncode == 1 and "can be read once only" in p.stderr and not os.path.exists(piped2),
              "%s %s from a pipe, %s threads: refused: %d %s" % (twice, args, threads, p.returncode, p.stderr))
if hasattr(os, "mkfifo"):
    fifo = os.path.join(work, "fifo")
    os.mkfifo(fifo)
    writer = threading.Thread(target=lambda: open(fifo, "w").write(open(cut).read()))
    writer.start()
    try:
        p = subprocess.run([exe, fifo, os.path.join(work, "fifo_out.obj")], capture_output=True, text=True, timeout=120)
        check(p.returncode == 1 and "can be read once only" in p.stderr, "a cut mesh from a FIFO: refused: %d %s" % (p.returncode, p.stderr))
    except subprocess.TimeoutExpired:
        check(False, "a cut mesh from a FIFO: the program waited for a second writer")
    writer.join()

# a VVAL file that cannot be written: OUT.obj was written (or replaced) first, exit 1
if os.path.exists("/dev/full"):
    vout = os.path.join(work, "vval_full.obj")
    for existing in [False, True]:
        if existing:
            with open(vout, "w") as f:
                f.write("old\n")
        rc, text = run(parallelogram, vout, "--integer-grid", "--grid-scale", "4", "--vval", "/dev/full")
        check(rc == 1 and (open(vout).read() == "old\n" if existing else not os.path.exists(vout)),
              "--vval /dev/full: exit 1, OUT.obj %s: %d %s" % ("unchanged" if existing else "not created", rc, text))

# --pin DIR and --features DIR read as empty lists (exit 0); now refused as the OBJ reader refuses a directory
for opt in ["--pin", "--features"]:
    dout = os.path.join(work, "list_dir.obj")
    rc, text = run(small, dout, opt, work)
    check(rc == 1 and "read error" in text and not os.path.exists(dout), "%s DIR: refused: %d %s" % (opt, rc, text))

# a replaced OUT.obj keeps its permission bits (a 0600 file became 0644); a dangling link gets its target created
if os.name == "posix":
    kept = os.path.join(work, "mode.obj")
    with open(kept, "w") as f:
        f.write("old\n")
    os.chmod(kept, 0o600)
    rc, text = run(small, kept, "--quiet")
    check(rc == 0 and (os.stat(kept).st_mode & 0o777) == 0o600, "OUT keeps mode 0600: %d %o" % (rc, os.stat(kept).st_mode))
    link, target = os.path.join(work, "dangling.obj"), os.path.join(work, "dangling_target.obj")
    os.symlink("dangling_target.obj", link)
    rc, text = run(small, link, "--quiet")
    check(rc == 0 and os.path.islink(link) and os.path.isfile(target), "a dangling link: its target created: %d %s" % (rc, text))
    # a loop of links: refused (a link of the loop that was not named was replaced by the OBJ, exit 0)
    loop = [os.path.join(work, "loop_%s.obj" % c) for c in "abc"]
    for a, b in zip(loop, loop[1:] + loop[:1]):
        os.symlink(os.path.basename(b), a)
    rc, text = run(small, loop[0], "--quiet")
    check(rc == 1 and "cannot write" in text and all(os.path.islink(l) for l in loop), "a loop of links: refused: %d %s" % (rc, text))
# a name of 238 to 255 bytes: the temporary name (NAME.tmp-XXXXXXXXXXXX) was too long
long_name = os.path.join(work, "n" * 251 + ".obj")
rc, text = run(small, long_name, "--quiet")
check(rc == 0 and os.path.isfile(long_name), "a 255-byte file name: %d %s" % (rc, text))
# a file option followed by another option or an empty name: a command-line error, not a file named "--quiet"
for opt in ["--report", "--vval", "--pin", "--features"]:
    for value in ["", "--quiet"]:
        if os.path.exists(os.path.join(work, "opt.obj")):
            os.remove(os.path.join(work, "opt.obj"))
        rc, text = run(small, os.path.join(work, "opt.obj"), "--integer-grid", opt, value)
        check(rc == 2 and "needs a file name" in text and not os.path.exists(os.path.join(work, "opt.obj")),
              "%s %r: exit 2: %d %s" % (opt, value, rc, text))

for f in failures:
    print("FAILED:", f)
print("cli_test: %d passed, %d failed" % (checks[0] - len(failures), len(failures)))
sys.exit(1 if failures else 0)
