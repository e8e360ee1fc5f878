"""CTest test of the seamless_quad command line: the quad mesh of CGAL's bear with an Orbifold Tutte
Parallelogram map (written by quad_figure) in OBJ, OFF and PLY, checked here from the files (every face a quad,
every edge in exactly two faces, V - E + F = 2, as many quads as the report's exact UV area; in PLY the patches:
every quad a cell of its patch's grid whose corners, read from patch_corner, give each grid point of a patch one
vertex, the report's patch sizes covering the quads; the --layout file: one polygon per patch, at the quad vertices'
points, through its patch's four grid corners in order, V - E + F = 2), and from it as a cut
mesh (welded automatically; refused with --no-weld); refusals with
exit 1 and nothing written: the Square map at grid scale 1 (its cones of 90 degrees, valence 1, within two cells of
each other; at grid scale 8 each cone's 2 x 2 cells are one quad, listed in the report's "split_cones", and
--no-cone-split refuses them), a map with fold-overs kept by
--no-untangle (FOLD_OVERS; untangled by default, it gives its quads),
a grid scale that is not a power of two; command-line errors (exit 2). With the shared data directory (optional
SHARED_DATA argument, skipped where it does not exist): libQEx's fandisk map, whose integer translations put a cone
pair onto one integer point, gives its quad mesh by default (the pair merged) and is refused with --keep-cone-pairs;
Directional's full-seamless dragon gives a closed quad mesh (chi 2) with its cone pairs on one point moved apart, and
with --no-cone-separation is refused with the zero-area triangles the snap proved forced named as such.
usage: python3 quad_cli_test.py SEAMLESS_QUAD PARALLELOGRAM.obj SQUARE.obj WORKDIR [SHARED_DATA]"""
import json
import os
import shutil
import subprocess
import sys

from cut_mesh import write_cut_mesh
from fold_over_grid import write_fold_over_grid

exe, parallelogram, square, work = sys.argv[1:5]
shared = sys.argv[5] if len(sys.argv) > 5 else ""
shutil.rmtree(work, ignore_errors=True)   # no file of an earlier run may pass a 'nothing written' check
os.makedirs(work, exist_ok=True)
checks, failures = [0], []


def check(ok, what):
    checks[0] += 1
    if not ok:
        failures.append(what)


def run(*args):
    p = subprocess.run([exe, *args], capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def faces_of(path):
    """the faces (0-based vertex indices) and the vertex count of an OBJ, OFF or ASCII PLY file"""
    lines = [l.split() for l in open(path) if l.split()]
    if path.endswith(".obj"):
        return sum(1 for l in lines if l[0] == "v"), [[int(c.split("/")[0]) - 1 for c in l[1:]] for l in lines if l[0] == "f"]
    if path.endswith(".off"):
        nv, nf = int(lines[1][0]), int(lines[1][1])
        return nv, [[int(x) for x in l[1:1 + int(l[0])]] for l in lines[2 + nv:2 + nv + nf]]
    end = next(i for i, l in enumerate(lines) if l[0] == "end_header")
    nv = next(int(l[2]) for l in lines if l[:2] == ["element", "vertex"])
    nf = next(int(l[2]) for l in lines if l[:2] == ["element", "face"])
    return nv, [[int(x) for x in l[1:1 + int(l[0])]] for l in lines[end + 1 + nv:end + 1 + nv + nf]]


def edge_uses(faces):
    """per undirected edge (smaller vertex first), the faces it is a side of"""
    edges = {}
    for f in faces:
        for i in range(len(f)):
            e = (min(f[i], f[(i + 1) % len(f)]), max(f[i], f[(i + 1) % len(f)]))
            edges[e] = edges.get(e, 0) + 1
    return edges


# 1. the parallelogram bear at grid scale 4, in the three formats
report = os.path.join(work, "quad.json")
for ext in ["obj", "off", "ply"]:
    out = os.path.join(work, "bear_quads." + ext)
    layout = os.path.join(work, "bear_layout.ply")
    rc, text = run(parallelogram, out, "--grid-scale", "4", "--report", report, *(["--layout", layout] if ext == "ply" else []))
    check(rc == 0 and "verified" in text, "%s: exit %d %s" % (ext, rc, text))
    if rc != 0:
        continue
    r = json.load(open(report))
    q = r["quad_mesh"]
    check(r["snap"]["status"] == "SUCCESS" and q["status"] == "SUCCESS" and q["covers_map"], "%s: report %s" % (ext, q))
    nv, faces = faces_of(out)
    edges = edge_uses(faces)
    check(all(len(f) == 4 for f in faces), "%s: every face a quad" % ext)
    check(all(n == 2 for n in edges.values()), "%s: every edge in exactly two quads (closed, manifold edges)" % ext)
    check(nv - len(edges) + len(faces) == 2 == q["euler_characteristic"], "%s: V - E + F = 2" % ext)
    check(len(faces) == q["quads"] and str(len(faces)) == q["uv_area"], "%s: %d quads, UV area %s" % (ext, len(faces), q["uv_area"]))
    check(q["irregular_vertices"] == q["cones"] == 4, "%s: 4 irregular vertices = the 4 cones" % ext)
    if ext == "ply":
        header = open(out).read().split("end_header")[0]
        check(all(p in header for p in ["input_kind", "input_face", "grid_u", "grid_v", "input_faces"]),
              "ply: the origin properties are written")
        face_props = [l.split()[2] for l in header.split("element face")[1].splitlines() if l.startswith("property int")]
        rows = [[int(x) for x in l.split()] for l in open(out).read().split("end_header")[1].split("\n")[1 + nv:] if l.strip()]
        pt = r["patches"]
        check(pt["status"] == "SUCCESS" and pt["all_rectangles"] and len(pt["sizes"]) == pt["patches"] and
              sum(w * h for w, h in pt["sizes"]) == len(faces), "ply: the report's patches cover the quads: %s" % pt)
        grid, cells, conflicts = {}, set(), 0
        for row in rows:
            n = row[0]
            f, prop = row[1:1 + n], dict(zip(face_props, row[1 + n:]))
            pid, i, j, c = prop["patch_id"], prop["patch_i"], prop["patch_j"], prop["patch_corner"]
            w, h = pt["sizes"][pid]
            conflicts += 0 if 0 <= i < w and 0 <= j < h and (pid, i, j) not in cells else 1
            cells.add((pid, i, j))
            for t, (di, dj) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):   # the cell's corners from (i, j) on
                conflicts += 0 if grid.setdefault((pid, i + di, j + dj), f[(c + t) % 4]) == f[(c + t) % 4] else 1
        check(len(rows) == len(faces) and conflicts == 0 and "patches: %d patches" % pt["patches"] in text,
              "ply: every quad a cell of its patch, each grid point one vertex: %d conflicts" % conflicts)
        # the layout: a polygon per patch through its grid's four corners in (cyclic) order, at the quad vertices' points
        lay = r["layout"]
        lv, lfaces = faces_of(layout)
        lrows = [l.split() for l in open(layout).read().split("end_header")[1].split("\n")[1:] if l.strip()]
        points = [l.split()[:3] for l in open(out).read().split("end_header")[1].split("\n")[1:1 + nv]]
        quad_vertex = [int(l[3]) for l in lrows[:lv]]
        check(lay["status"] == "SUCCESS" and lay["faces"] == len(lfaces) == pt["patches"] and lay["vertices"] == lv and
              lv - lay["arcs"] + len(lfaces) == 2 and all(lrows[k][:3] == points[quad_vertex[k]] for k in range(lv)),
              "ply layout: a face per patch, chi 2, each vertex at its quad vertex: %s" % lay)
        sizes_ok = True
        for p, l in enumerate(lrows[lv:lv + len(lfaces)]):
            n = int(l[0])
            polygon, (w, h) = [quad_vertex[int(x)] for x in l[1:1 + n]], [int(x) for x in l[1 + n:3 + n]]
            corners = [grid.get((p, i, j)) for i, j in [(0, 0), (w, 0), (w, h), (0, h)]]
            at = [polygon.index(c) for c in corners if c in polygon]
            sizes_ok &= [w, h] == pt["sizes"][p] and len(at) == 4 and sum(at[(k + 1) % 4] < at[k] for k in range(4)) == 1
        check(sizes_ok, "ply layout: each face its patch's size, through the patch's four corners in order")

# 1b. the same map as a cut mesh (vertices duplicated along the seams, as Directional writes): welded automatically,
# the same quad mesh; refused with --no-weld (its seams would be borders), nothing written
cut = os.path.join(work, "bear_cut.obj")
write_cut_mesh(parallelogram, cut)
out = os.path.join(work, "bear_cut_quads.obj")
rc, text = run(cut, out, "--grid-scale", "4")
check(rc == 0 and "welded automatically" in text and os.path.exists(out) and
      [n if i == 0 else len(n) for i, n in enumerate(faces_of(out))] ==
      [n if i == 0 else len(n) for i, n in enumerate(faces_of(os.path.join(work, "bear_quads.obj")))],
      "cut mesh: welded automatically, the same quad mesh: %d %s" % (rc, text))
out = os.path.join(work, "bear_cut_noweld.obj")
rc, text = run(cut, out, "--grid-scale", "4", "--no-weld")
check(rc == 1 and "cut mesh" in text and not os.path.exists(out), "cut mesh with --no-weld: refused: %d %s" % (rc, text))
rc, text = run(cut, out, "--weld", "--no-weld")
check(rc == 2, "--weld with --no-weld: a command-line error: %d" % rc)

# 1c. the same map with its UVs times 1.3: its translations and cones are integers at no grid scale; refused (the map
# was never quantized) without --quantize, nothing written; with it, quantized and extracted with every check
scaled = os.path.join(work, "bear_scaled.obj")
with open(parallelogram) as f, open(scaled, "w") as g:
    for line in f:
        p = line.split()
        g.write("vt %r %r\n" % (float(p[1]) * 1.3, float(p[2]) * 1.3) if p and p[0] == "vt" else line)
out = os.path.join(work, "bear_scaled_quads.obj")
rc, text = run(scaled, out, "--grid-scale", "4")
check(rc == 1 and "not quantized" in text and "--quantize" in text and not os.path.exists(out),
      "scaled map without --quantize: refused, nothing written: %d %s" % (rc, text))
scaled_report = os.path.join(work, "bear_scaled.json")
rc, text = run(scaled, out, "--grid-scale", "4", "--quantize", "--report", scaled_report)
rep = json.load(open(scaled_report)) if os.path.exists(scaled_report) else {}
check(rc == 0 and "verified" in text and os.path.exists(out) and rep.get("snap", {}).get("quantized") is True and
      rep.get("quad_mesh", {}).get("irregular_vertices") == rep["snap"]["field_cones"] == 4,
      "scaled map with --quantize: quantized, a verified quad mesh with the 4 cones irregular: %d %s" % (rc, text))

# 2. refusals: exit 1, nothing written, the reason on stderr (and in the report)
folds = os.path.join(work, "folds.obj")
write_fold_over_grid(folds)
for src, args, words, where in [(square, [], "valence 1", "quad_mesh"), (folds, ["--no-untangle"], "FOLD_OVERS", "quad_mesh")]:
    out = os.path.join(work, "refused.obj")
    rc, text = run(src, out, "--report", report, *args)
    check(rc == 1 and words in text and not os.path.exists(out), "refused (%s): exit %d %s" % (words, rc, text))
    check((where == "snap") == ("after snapping" not in text), "refused (%s): counts after snapping only if it snapped" % words)
    r = json.load(open(report))
    check(r[where]["status"] != "SUCCESS", "refused (%s): the report says so" % words)
    if words == "FOLD_OVERS":
        check(len(r["quad_mesh"]["fold_overs"]) > 0, "FOLD_OVERS: the report lists the fold-overs")

# the Square map at grid scale 8: its two cones of 90 degrees split (3 quads fewer than the UV area each), a closed
# quad mesh; with --no-cone-split refused, nothing written
out = os.path.join(work, "square_quads.obj")
rc, text = run(square, out, "--grid-scale", "8", "--report", report)
q = json.load(open(report))["quad_mesh"]
nv, faces = faces_of(out) if rc == 0 else (0, [])
check(rc == 0 and len(q["split_cones"]) == 2 and len(faces) == q["quads"] and nv == q["quad_vertices"] and q["euler_characteristic"] == 2 and
      q["quads"] + 6 == int(q["uv_area"]) and "2 of valence 1 split, into 3 of valence 3 each" in text,
      "Square map at grid scale 8: its two cones of 90 degrees split: %d %s" % (rc, text))
os.remove(out)
rc, text = run(square, out, "--grid-scale", "8", "--no-cone-split")
check(rc == 1 and "(a cone of valence 1)" in text and not os.path.exists(out), "--no-cone-split: refused: %d %s" % (rc, text))

# a grid scale that is not a power of two is a command-line error (exit 2, as a value that is not a number; it was
# exit 1, refused by the snap), nothing written
for bad in ["3", "0", "-1", "nan", "inf"]:
    out = os.path.join(work, "refused.obj")
    rc, text = run(parallelogram, out, "--grid-scale", bad)
    check(rc == 2 and "power of two" in text and not os.path.exists(out), "--grid-scale %s: exit 2: %d %s" % (bad, rc, text))

for opt, bad in [("--threads", " -1"), ("--threads", "+2"), ("--max-grid-cells", "-5"), ("--max-grid-cells", "1e3")]:
    out = os.path.join(work, "refused.obj")
    rc, text = run(parallelogram, out, opt, bad)
    check(rc == 2 and not os.path.exists(out), "%s %r: exit 2: %d %s" % (opt, bad, rc, text))

# the fold-over grid untangled (the default): a valid quad mesh of the 3 x 3 grid, 9 quads, 16 vertices
out = os.path.join(work, "untangled.obj")
rc, text = run(folds, out, "--report", report)
r = json.load(open(report)) if os.path.exists(report) else {}
check(rc == 0 and r.get("snap", {}).get("flips_before") == 2 and r.get("quad_mesh", {}).get("quads") == 9,
      "the fold-over grid, untangled, gives its 9 quads: %d %s" % (rc, text))
if rc == 0:
    lines = [l.split() for l in open(out)]
    check(sum(1 for p in lines if p and p[0] == "v") == 16 and sum(1 for p in lines if p and p[0] == "f") == 9,
          "untangled fold-over grid: 16 quad vertices, 9 quads written")

# 2b. a collapsed cone pair (shared data only): merged by default, kept with --keep-cone-pairs (then refused)
fandisk = os.path.join(shared, "libqex", "fandisk_param.obj")
if shared and os.path.exists(fandisk):
    out = os.path.join(work, "fandisk.obj")
    rc, text = run(fandisk, out, "--report", report)
    r = json.load(open(report))
    check(rc == 0 and len(r["snap"]["merged_cone_pairs"]) > 0 and r["quad_mesh"]["status"] == "SUCCESS" and
          r["quad_mesh"]["irregular_vertices"] == r["snap"]["field_cones"] and os.path.exists(out) and
          "merged 1 cone pair(s)" in text and "--keep-cone-pairs keeps them" in text,
          "fandisk: the cone pair merged, its quad mesh written: %d %s" % (rc, text))
    # at grid scale 8 the same pairs are merged and the quad mesh has the same irregular vertices: the merge reaches
    # S cells at grid scale S (with one cell at every scale, 32 irregular vertices instead of 28 at 8)
    merged, valences, quads = r["snap"]["merged_cone_pairs"], r["quad_mesh"]["valence_histogram"], r["quad_mesh"]["quads"]
    out = os.path.join(work, "fandisk_8.obj")
    rc, text = run(fandisk, out, "--grid-scale", "8", "--report", report)
    r = json.load(open(report))
    def irregular(histogram):   # vertices per valence but 4
        return {k: n for k, n in enumerate(histogram) if k != 4 and n > 0}
    check(rc == 0 and r["snap"]["merged_cone_pairs"] == merged and r["quad_mesh"]["quads"] == 64 * quads and
          irregular(r["quad_mesh"]["valence_histogram"]) == irregular(valences),
          "fandisk at grid scale 8: the same pairs merged, the same irregular vertices: %d %s" % (rc, text))
    out = os.path.join(work, "fandisk_kept.obj")
    rc, text = run(fandisk, out, "--keep-cone-pairs", "--report", report)
    r = json.load(open(report))
    check(rc == 1 and "onto one integer point" in text and not os.path.exists(out) and r["snap"]["merged_cone_pairs"] == [],
          "fandisk with --keep-cone-pairs: refused, nothing written: %d %s" % (rc, text))
else:
    print("quad_cli_test: fandisk: SKIPPED (no shared data directory '%s')" % shared)


def closed_quads(rc, out, q):
    """the run wrote a closed all-quad mesh of Euler characteristic 2 with the quads of the report"""
    if rc != 0 or not os.path.exists(out):
        return False
    nv, faces = faces_of(out)
    edges = edge_uses(faces)
    return (all(len(f) == 4 for f in faces) and all(c == 2 for c in edges.values()) and
            nv - len(edges) + len(faces) == 2 and len(faces) == q["quads"])


# 2c. cone pairs a cut joins on one integer point (shared data only): Directional's dragon, whose rounded translations
# put such pairs onto one point, gives a closed quad mesh by default (the pairs moved apart; a branch point's cell
# filled together with the cell of a 90-degree cone next to it); with --no-cone-separation the pairs stay and it keeps 8
# zero-area triangles: refused, the snap proved them forced, one named
dragon = os.path.join(shared, "directional", "dragon-param-full-seamless.obj")
if shared and os.path.exists(dragon):
    out = os.path.join(work, "dragon.obj")
    rc, text = run(dragon, out, "--report", report)
    r = json.load(open(report))
    q = r["quad_mesh"]
    check(closed_quads(rc, out, q) and len(r["snap"]["separated_cone_pairs"]) > 0 and "moved %d cone pair(s) apart" %
          len(r["snap"]["separated_cone_pairs"]) in text and len(q["absorbed_cones"]) > 0 and
          len(q["filled_branch_points"]) > 0 and q["covers_map"],
          "dragon: a closed quad mesh, chi 2, the cone pairs separated: %d %s" % (rc, text))
    # at grid scale 2 the cut joining the pair 5023 + 5025 (vertex numbers of the welded mesh, as the report gives them)
    # runs farther than 2 cells from their point: the separation
    # reaches 2 S cells at scale S (with 2 cells the pair stayed, two zero-area triangles, refused)
    out = os.path.join(work, "dragon_2.obj")
    rc, text = run(dragon, out, "--grid-scale", "2", "--report", report)
    r = json.load(open(report))
    check(closed_quads(rc, out, r["quad_mesh"]) and [5023, 5025] in r["snap"]["separated_cone_pairs"] and
          r["quad_mesh"]["covers_map"], "dragon at grid scale 2: a closed quad mesh, chi 2: %d %s" % (rc, text))
    out = os.path.join(work, "dragon_kept.obj")
    rc, text = run(dragon, out, "--no-cone-separation", "--report", report)
    r = json.load(open(report))
    forced = [f for f in r["snap"]["folds"] if f["forced"]]
    wound = r["snap"]["winding_defects"]
    forced_wound = [w for w in wound if w["forced"]]   # corners of the forced faces
    check(rc == 1 and not os.path.exists(out) and r["quad_mesh"]["status"] == "FOLD_OVERS" and len(forced) > 0 and
          ("the snap proved %d of them forced" % len(forced)) in text and forced[0]["message"] in text and
          0 < len(forced_wound) < len(wound) and r["snap"]["separated_cone_pairs"] == [] and
          "untangle the map first" not in r["quad_mesh"]["message"] + r["quad_mesh"]["advice"] and
          "untangled the map already" in r["quad_mesh"]["advice"] and
          ("around %d vertices (%d of them corners of the forced faces)" % (len(wound), len(forced_wound))) in text,
          "dragon with --no-cone-separation: refused, the forced faces and the wound vertices at them said to be "
          "forced: %d %s" % (rc, text))
else:
    print("quad_cli_test: dragon: SKIPPED (no shared data directory '%s')" % shared)

# 3. command-line errors and --help
rc, text = run(parallelogram, os.path.join(work, "x.stl"))
check(rc == 2 and ".obj, .off or .ply" in text, "unknown output format: %d %s" % (rc, text))
rc, text = run(parallelogram)
check(rc == 2, "missing OUT: %d" % rc)
rc, text = run("--help")
for opt in ["--weld", "--no-weld", "--grid-scale", "--quantize", "--no-untangle", "--keep-cone-pairs", "--report", "--quiet",
            "--help"]:
    check(rc == 0 and opt in text, "--help lists " + opt)

# OUT or --report naming the input: the map would be replaced by the quad mesh (it was): exit 2, the input unchanged
copy = os.path.join(work, "input_copy.obj")
shutil.copyfile(parallelogram, copy)
before = open(copy, "rb").read()
for args in [[copy], [os.path.join(work, "out_in.obj"), "--report", copy]]:
    rc, text = run(copy, *args, "--grid-scale", "4")
    check(rc == 2 and "name one file" in text and open(copy, "rb").read() == before,
          "an output naming IN: exit 2, IN unchanged: %d %s" % (rc, text))

# OUT and --layout naming one file: the layout would replace the quad mesh, and the run would still say both were
# written: refused (exit 2), nothing written
clash = os.path.join(work, "clash.obj")
rc, text = run(parallelogram, clash, "--grid-scale", "4", "--layout", os.path.join(work, ".", "clash.obj"))
check(rc == 2 and "name one file" in text and not os.path.exists(clash), "OUT = --layout: exit 2: %d %s" % (rc, text))

# OUT in a directory that does not exist: exit 1, and the report (written before the mesh) says the run failed: "error",
# "output" null (it named the output, with every status SUCCESS)
late = os.path.join(work, "late.json")
rc, text = run(parallelogram, os.path.join(work, "no_such_dir", "q.obj"), "--grid-scale", "4", "--report", late)
r = json.load(open(late))
check(rc == 1 and r["output"] is None and "no_such_dir" in r["error"] and r["quad_mesh"]["status"] == "SUCCESS",
      "OUT in a missing directory: exit 1, the report says why: %d %s" % (rc, text))

# an input that cannot be read: exit 1, no mesh, and the report says why (the help: "also on failure")
unreadable, unreadable_report = os.path.join(work, "missing.obj"), os.path.join(work, "missing.json")
rc, text = run(unreadable, os.path.join(work, "missing_out.obj"), "--report", unreadable_report)
rep = json.load(open(unreadable_report)) if os.path.exists(unreadable_report) else {}
check(rc == 1 and not os.path.exists(os.path.join(work, "missing_out.obj")) and rep.get("quad_mesh", 0) is None and
      rep.get("snap", {}).get("status") == "INVALID_INPUT" and "cannot read input" in rep.get("snap", {}).get("message", "") and
      rep.get("output", 0) is None and "cannot read input" in rep.get("error", ""),   # "output" was OUT's name, no "error"
      "unreadable input: exit 1, the report written: %d %s %s" % (rc, text, rep))

# a --layout file that cannot be written: OUT was written first, and the report said "output": null; now the layout
# goes to its temporary file before OUT is written, so neither is, and the report's null is true
lost_out, lost_report = os.path.join(work, "lost_layout.obj"), os.path.join(work, "lost_layout.json")
rc, text = run(parallelogram, lost_out, "--grid-scale", "4", "--report", lost_report, "--layout",
               os.path.join(work, "no_such_dir", "layout.ply"))
rep = json.load(open(lost_report)) if os.path.exists(lost_report) else {}
check(rc == 1 and not os.path.exists(lost_out) and rep.get("output", 0) is None and "error" in rep,
      "--layout that cannot be written: exit 1, no OUT, the report's output null: %d %s %s" % (rc, text, rep.get("output", 0)))

for f in failures:
    print("FAILED:", f)
print("quad_cli_test: %d passed, %d failed" % (checks[0] - len(failures), len(failures)))
sys.exit(1 if failures else 0)
