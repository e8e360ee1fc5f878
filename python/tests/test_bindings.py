"""Tests of the Python bindings. Exactness is checked here, independently of the C++ checker, in
rational arithmetic (fractions.Fraction holds every double exactly). Bit-for-bit comparisons are of the package's
own outputs on inputs made in the same process (an exact input returned as it is, a scaled result, OBJ text written
and read back with correctly rounded conversions): none compares a floating-point result of libm or of a solver
with stored bits, so none depends on the machine."""
import os
import random
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import seamless_snapping as ss

SHARED = os.environ.get("SS_SHARED_DATA_DIR", "")


def shared_map(name):
    """ss.read_obj() of the file `name` of ../shared/data (SS_SHARED_DATA_DIR), or the test skipped where it is absent"""
    path = os.path.join(SHARED, name)
    if not SHARED or not os.path.exists(path):
        pytest.skip("shared data not present: " + path)
    return ss.read_obj(path)


def parse_obj(path):
    """V, F, UV, FUV of an OBJ with per-corner vt (triangles; 'f v/vt', 'f v/vt/vn', negative indices), parsed here
    in Python (float() is correctly rounded): the reference for ss.read_obj."""
    V, UV, F, FUV = [], [], [], []
    with open(path) as fh:
        for line in fh:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                V.append([float(x) for x in t[1:4]])
            elif t[0] == "vt":
                UV.append([float(x) for x in t[1:3]])
            elif t[0] == "f":
                vs, ts = [], []
                for c in t[1:]:
                    p = c.split("/")
                    v, vt = int(p[0]), int(p[1])
                    vs.append(v - 1 if v > 0 else len(V) + v)
                    ts.append(vt - 1 if vt > 0 else len(UV) + vt)
                assert len(vs) == 3
                F.append(vs)
                FUV.append(ts)
    return np.array(V), np.array(F), np.array(UV), np.array(FUV)


def rot(k, p):
    x, y = p
    for _ in range(k % 4):
        x, y = -y, x
    return (x, y)


def seam_violations(V, F, UV, FUV, weld, translations=None):
    """Cut edges whose two sides are not related by an exact rotation k*90 + translation (Eq. 4), in
    Fractions. Vertices with bit-identical positions are one vertex when `weld`. The translations of the
    exact ones are appended to `translations` when given."""
    key = {}
    vid = []
    for p in V:
        k = tuple(p.tolist()) if weld else len(vid)
        vid.append(key.setdefault(k, len(key)))
    corner = {}   # directed edge (a, b) -> (uv of a, uv of b) in the face that holds it
    for f in range(len(F)):
        for k in range(3):
            a, b = vid[F[f][k]], vid[F[f][(k + 1) % 3]]
            ua = tuple(Fraction(x) for x in UV[FUV[f][k]])
            ub = tuple(Fraction(x) for x in UV[FUV[f][(k + 1) % 3]])
            corner[(a, b)] = (ua, ub)
    bad, cut = 0, 0
    for (a, b), (pa, pb) in corner.items():
        if (b, a) not in corner or a > b:
            continue
        qb, qa = corner[(b, a)]
        if pa == qa and pb == qb:
            continue
        cut += 1
        ok = False
        for k in range(4):
            ra, rb = rot(k, pa), rot(k, pb)
            ta = (qa[0] - ra[0], qa[1] - ra[1])
            tb = (qb[0] - rb[0], qb[1] - rb[1])
            if ta == tb:
                ok = True
                if translations is not None:
                    translations.append(ta)
                break
        bad += 0 if ok else 1
    return bad, cut


def cut_grid(n=8, noise=1e-12, seed=1, size=1.0, t=(3.25, 0.5)):
    """A planar n x n grid of side `size` whose upper half is rotated by 90 degrees and translated by `t`
    (one cut line from border to border, no cone), with the upper corners perturbed by `noise`: seamless
    up to noise."""
    rng = random.Random(seed)
    V = [[size * i / n, size * j / n, 0.0] for j in range(n + 1) for i in range(n + 1)]
    F, FUV, UV = [], [], []
    idx = lambda i, j: j * (n + 1) + i
    half = n // 2
    for j in range(n):
        for i in range(n):
            for tri in ((idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)), (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1))):
                above = j >= half
                ts = []
                for v in tri:
                    x, y = V[v][0], V[v][1]
                    if above:
                        x, y = -y + t[0] + rng.uniform(-noise, noise), x + t[1] + rng.uniform(-noise, noise)
                    UV.append([x, y])
                    ts.append(len(UV) - 1)
                F.append(list(tri))
                FUV.append(ts)
    return np.array(V), np.array(F), np.array(UV), np.array(FUV)


def test_snap_generated_cut_grid():
    V, F, UV, FUV = cut_grid()
    bad, cut = seam_violations(V, F, UV, FUV, weld=False)
    assert cut > 0 and bad > 0, "the generated input must be inexact"
    assert not ss.is_exactly_seamless(V, F, UV, FUV)
    UV2, FUV2, report = ss.snap(V, F, UV, FUV)
    assert report["status"] == "SUCCESS"
    assert FUV2.shape == FUV.shape
    bad2, cut2 = seam_violations(V, F, UV2, FUV2, weld=False)
    assert bad2 == 0 and cut2 == cut
    assert ss.is_exactly_seamless(V, F, UV2, FUV2)
    assert np.max(np.abs(UV2[FUV2] - UV[FUV])) < 1e-9        # a small change
    # an exact input comes back unchanged
    UV3, FUV3, report3 = ss.snap(V, F, UV2, FUV2)
    assert np.array_equal(UV3, UV2) and np.array_equal(FUV3, FUV2)


def test_snap_integer_grid_map():
    # side 8 on an 8 x 8 grid: every vertex on an integer point, translation (3, 1) up to noise
    V, F, UV, FUV = cut_grid(n=8, noise=1e-9, size=8.0, t=(3.0, 1.0))
    assert not ss.is_exact_integer_grid_map(V, F, UV, FUV)
    UV2, FUV2, report = ss.snap(V, F, UV, FUV, integer_grid_map=True)
    assert report["status"] == "SUCCESS"
    translations = []
    bad, cut = seam_violations(V, F, UV2, FUV2, weld=False, translations=translations)
    assert bad == 0 and cut > 0 and len(translations) == cut
    assert all(c.denominator == 1 for tr in translations for c in tr), "integer translations, exactly"
    # u -> R u + (3, 1) from the lower half to the upper one, or its inverse u -> R^-1 u + (-1, 3)
    assert set(translations) <= {(Fraction(3), Fraction(1)), (Fraction(-1), Fraction(3))}
    assert ss.is_exact_integer_grid_map(V, F, UV2, FUV2)
    assert np.max(np.abs(UV2[FUV2] - UV[FUV])) < 1e-8
    # a map whose integer grid is at multiples of 1/2: the same map scaled by 1/2, grid_scale 2, bit for bit
    UV4, FUV4, _ = ss.snap(V, F, UV / 2, FUV, integer_grid_map=True, grid_scale=2.0)
    assert np.array_equal(UV4, UV2 / 2) and ss.is_exact_integer_grid_map(V, F, UV4, FUV4, grid_scale=2.0)
    # far from integers (translation 3.25): refused, nothing returned
    Vq, Fq, UVq, FUVq = cut_grid(n=8, noise=1e-9, size=8.0, t=(3.25, 1.0))
    with pytest.raises(ss.SnapError) as e:
        ss.snap(Vq, Fq, UVq, FUVq, integer_grid_map=True)
    assert e.value.report["status"] == "INVALID_INPUT"
    # tolerances that are NaN or negative: refused (NaN used to pass as "no bound" or "align nothing")
    for name in ("max_untangle_change", "alignment_tolerance", "rotation_tolerance"):
        for bad in (float("nan"), -1.0):
            with pytest.raises(ss.SnapError) as e:
                ss.snap(V, F, UV, FUV, integer_grid_map=True, **{name: bad})
            assert e.value.report["status"] == "INVALID_INPUT" and e.value.report["message"].startswith(name + " = ")


def test_diagnose_seamlessness():
    V, F, UV, FUV = cut_grid(noise=1e-12)
    d = ss.diagnose_seamlessness(V, F, UV, FUV)
    assert d["status"] == "SUCCESS" and not d["exact"] and 0 < d["violated_rows"] <= d["rows"]
    assert d["kind"] == "transition" and isinstance(d["residual"], Fraction)
    assert 0 < abs(d["residual"]) <= 4e-12 and d["residual_double"] == float(d["residual"])
    assert "residual 0.000000" not in d["message"] and "UV units (exactly " in d["message"]   # (it printed 6 decimals)
    # recomputed here in Fractions: the worst residual is the largest mismatch of an edge's transition at its two ends,
    # over the edges whose two faces give different UVs (the upper corners are perturbed one by one, so the upper
    # half's edges are cut edges too), with the quarter turn that maps one side onto the other
    uv = lambda f, v: next(tuple(Fraction(c) for c in UV[FUV[f][k]]) for k in range(3) if F[f][k] == v)
    turn = lambda k, p: p if k == 0 else turn(k - 1, (-p[1], p[0]))
    faces_of = {}
    for f in range(len(F)):
        for k in range(3):
            faces_of.setdefault(tuple(sorted((F[f][k], F[f][(k + 1) % 3]))), []).append(f)
    mismatch = {}
    for (a, b), fs in faces_of.items():
        if len(fs) != 2:
            continue
        f, g = fs
        ef, eg = [tuple(uv(h, b)[c] - uv(h, a)[c] for c in range(2)) for h in (f, g)]
        k = min(range(4), key=lambda k: sum(abs(x - y) for x, y in zip(turn(k, ef), eg)))
        t = [tuple(uv(g, v)[c] - turn(k, uv(f, v))[c] for c in range(2)) for v in (a, b)]
        mismatch[(a, b)] = max(abs(t[0][c] - t[1][c]) for c in range(2))
    worst = max(mismatch.values())
    assert abs(d["residual"]) == worst and mismatch[tuple(sorted(d["edge"]))] == worst
    assert len(d["corners"]) >= 2 and all(0 <= f < len(F) and F[f][k] in d["edge"] for f, k in d["corners"])
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV)
    d2 = ss.diagnose_seamlessness(V, F, UV2, FUV2)
    assert d2["exact"] and d2["violated_rows"] == 0 and d2["rows"] == d["rows"] and "residual" not in d2
    assert d2["exact"] == ss.is_exactly_seamless(V, F, UV2, FUV2)
    # integer-grid rows: a map whose translation (3.25, 0.5) is not an integer is refused as the snap refuses it; one
    # snapped to an integer-grid map holds them all
    d3 = ss.diagnose_seamlessness(V, F, UV2, FUV2, integer_grid_map=True)
    assert d3["status"] == "INVALID_INPUT" and "not near an integer-grid map" in d3["message"]
    Vc, Fc, UVc, FUVc = cut_grid(n=8, noise=1e-9, size=8.0, t=(3.0, 1.0))
    UV3, FUV3, _ = ss.snap(Vc, Fc, UVc, FUVc, integer_grid_map=True)
    d4 = ss.diagnose_seamlessness(Vc, Fc, UV3, FUV3, integer_grid_map=True)
    assert d4["status"] == "SUCCESS" and d4["exact"] and d4["rows"] > ss.diagnose_seamlessness(Vc, Fc, UV3, FUV3)["rows"]
    assert not ss.diagnose_seamlessness(Vc, Fc, UVc, FUVc, integer_grid_map=True)["exact"]
    bad = ss.diagnose_seamlessness(V, F[:, :2], UV, FUV)
    assert bad["status"] == "INVALID_INPUT" and "3 columns" in bad["message"] and bad["exact"] is None and bad["rows"] == 0


def orientations(F, UV, FUV):
    """the sign of every UV triangle, exactly (Fractions of the doubles)"""
    out = []
    for f in range(len(F)):
        a, b, c = [tuple(Fraction(x) for x in UV[FUV[f, m]]) for m in range(3)]
        d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        out.append((d > 0) - (d < 0))
    return out


def test_messages_of_files_in_other_encodings(tmp_path):
    # a Latin-1 byte in a token of the file: InputError names it (as its Latin-1 character); the message was empty
    path = tmp_path / "latin.obj"
    path.write_bytes(b"v 0 0 0\nv 1 0 0\nv 0 1 \xe9x\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n")
    with pytest.raises(ss.InputError, match="\u00e9x"):
        ss.read_obj(str(path))


def test_change_statistics_scale_covariant():
    # the report's changes scale with the map (2^j, bit for bit) down to 2^-500 and up to 2^1000, where summing the
    # squares in the caller's units gave an RMS of 0 next to a positive max, and NaN (JSON null)
    V, F, UV, FUV = cut_grid(n=8, noise=1e-9)
    _, _, r = ss.snap(V, F, UV, FUV)
    assert r["snap_max_change"] > 0 and r["snap_rms_change"] > 0
    for j in (-500, 1000):
        _, _, rj = ss.snap(V, F, UV * 2.0 ** j, FUV)
        for key in ("snap_max_change", "snap_rms_change", "total_rms_change"):
            assert rj[key] == r[key] * 2.0 ** j, (j, key, rj[key], r[key])


def test_untangle_integer_grid_map():
    # an exact integer-grid map (grid of side 16, every vertex on an integer point) with one interior vertex of
    # the lower half dragged across its neighbour: its UV triangles fold over
    V, F, UV, FUV = cut_grid(n=16, noise=0.0, size=16.0, t=(3.0, 1.0))
    UV = UV.copy()
    dragged = 3 * 17 + 3                                 # vertex (3, 3) of the 17 x 17 grid of vertices
    for f in range(len(F)):
        for m in range(3):
            if F[f, m] == dragged:
                UV[FUV[f, m]] = [4.6, 3.3]
    assert min(orientations(F, UV, FUV)) < 0
    # without untangling the fold-overs stay, each listed with its reason
    _, _, kept = ss.snap(V, F, UV, FUV, integer_grid_map=True, untangle=False)
    assert kept["untangled"] is False and kept["flips_after_repair"] > 0
    assert len(kept["folds"]) == kept["flips_after_repair"] + kept["degenerate_after_repair"]
    assert all(not x["forced"] and x["reason"] == "NOT_PROVEN_FORCED" for x in kept["folds"])
    # the default in integer-grid mode untangles: every triangle positive (exactly), still an exact IGM,
    # and only the vertices near the fold moved
    UV2, FUV2, report = ss.snap(V, F, UV, FUV, integer_grid_map=True)
    assert report["untangle"] and report["untangled"]
    assert min(orientations(F, UV2, FUV2)) > 0
    assert report["flips_after_repair"] == 0 and report["degenerate_after_repair"] == 0 and report["folds"] == []
    assert ss.is_exact_integer_grid_map(V, F, UV2, FUV2)
    # local: the UVs of the vertices more than 2 + 2 + 1 rings (untangling at k = 1 or 2, polish, propagation
    # along the aligned border) from the dragged vertex are bit for bit those of the input
    moved = {int(F[f, m]) for f in range(len(F)) for m in range(3) if tuple(UV2[FUV2[f, m]]) != tuple(UV[FUV[f, m]])}
    assert dragged in moved
    assert all(max(abs(v % 17 - 3), abs(v // 17 - 3)) <= 5 for v in moved), sorted(moved)
    assert report["untangle_rings"] <= 2 and 0 < report["untangle_max_change"] < 2.0
    assert report["untangle_attempts"] >= 1 and report["untangle_newton_steps"] >= report["untangle_attempts"] > 0
    assert 0 <= report["untangle_polish_steps"] <= 50
    # a bound on the change refuses the untangled map: the fold-overs stay, and the report says so
    _, _, refused = ss.snap(V, F, UV, FUV, integer_grid_map=True, max_untangle_change=1e-3)
    assert refused["untangle_refused"] and refused["flips_after_repair"] > 0
    assert not report["uv_mirrored"] and not refused["uv_mirrored"]
    # the same map mirrored (v -> -v, as a flipped texture convention gives it): not untangled, reported as mirrored
    UVm = UV.copy()
    UVm[:, 1] = -UVm[:, 1]
    _, _, mirrored = ss.snap(V, F, UVm, FUV, integer_grid_map=True)
    assert mirrored["uv_mirrored"] and not mirrored["untangled"] and "mirrored" in mirrored["message"]
    assert mirrored["flips_after_repair"] > len(F) // 2
    # the folded map and, beside it, a mirrored copy as a second component (the map as a whole is not mirrored): the
    # first is untangled, the mirrored one left alone (it was turned over, its UVs moved by many grid cells)
    V2 = np.vstack([V, V + [100.0, 0.0, 0.0]])
    F2 = np.vstack([F, F + len(V)])
    UV2 = np.vstack([UV, UVm])
    FUV2 = np.vstack([FUV, FUV + len(UV)])
    UV3, FUV3, both = ss.snap(V2, F2, UV2, FUV2, integer_grid_map=True)
    signs = orientations(F2, UV3, FUV3)
    assert both["uv_mirrored"] and both["untangled"] and "left the mirrored parts" in both["message"]
    assert min(signs[:len(F)]) > 0 and sum(1 for x in signs[len(F):] if x < 0) > len(F) // 2
    assert both["untangle_max_change"] < 2.0
    assert all("mirrored part" in x["message"] for x in both["folds"]) and len(both["folds"]) >= len(F) // 2


def test_closed_surface_without_cuts():
    # UVs given per vertex (no seam) on a closed mesh, as a projection or a placeholder makes them: every map of a
    # closed surface into the plane folds, so the snap says so for its folds and leaves the map as it is
    V, F, _, _ = flat_torus(n=4)
    # (mirrored too: its triangles are mostly negative, but such a part folds in every map: not called mirrored)
    for UV in (V[:, :2].copy(), V[:, :2] * np.array([-1.0, 1.0]), np.zeros((len(V), 2))):
        UV2, FUV2, report = ss.snap(V, F, UV, F, untangle=True)
        assert report["status"] == "SUCCESS" and report["closed_uncut_faces"] == len(F) and not report["untangled"]
        assert not report["uv_mirrored"]
        assert report["folds"] and report["folds_forced"] == 0
        assert all("closed part of the surface" in x["message"] for x in report["folds"])
        assert np.array_equal(UV2[FUV2], UV[F])


def test_snap_failure_is_reported_and_raises():
    V, F, UV, FUV = cut_grid()
    UV = UV.copy()
    UV[0, 0] = np.nan
    with pytest.raises(ss.SnapError) as e:
        ss.snap(V, F, UV, FUV)
    assert e.value.report["status"] == "INVALID_INPUT"
    uv, fuv, report = ss.snap(V, F, UV, FUV, raise_on_failure=False)
    assert uv is None and fuv is None and report["status"] == "INVALID_INPUT"
    with pytest.raises(ss.SnapError):
        ss.snap(V, F[:, :2], UV, FUV)


def exact_rows(C, b, x):
    C = C.tocsr()
    for i in range(C.shape[0]):
        s = sum(Fraction(int(v)) * Fraction(x[j]) for j, v in zip(C.indices[C.indptr[i]:C.indptr[i + 1]],
                                                                   C.data[C.indptr[i]:C.indptr[i + 1]]))
        if s != b[i]:
            return False
    return True


def test_project_scipy_sparse():
    sp = pytest.importorskip("scipy.sparse")
    rng = np.random.default_rng(3)
    n, m = 60, 25
    rows, cols, vals = [], [], []
    for i in range(m):                       # seamless-like rows: x_a - x_b + x_c - x_d = 0
        a, b_, c, d = rng.choice(n, 4, replace=False)
        rows += [i] * 4
        cols += [a, b_, c, d]
        vals += [1, -1, 1, -1]
    C = sp.coo_matrix((vals, (rows, cols)), shape=(m, n))
    b = np.zeros(m, dtype=np.int64)
    xbar = rng.uniform(-1, 1, n)
    assert not exact_rows(C, b, xbar)
    x, report = ss.project(C.tocsc(), b, xbar)
    assert report["status"] == "SUCCESS"
    assert exact_rows(C, b, x)
    assert np.max(np.abs(x - xbar)) < 10   # bounded; the exact check above is the point
    # the same system as a dense integer array
    x2, _ = ss.project(C.toarray(), b, xbar)
    assert exact_rows(C, b, x2)


def test_project_unsigned_beyond_int64():
    # uint64 entries of 2^63 or more used to wrap around to negative int64 values: a "SUCCESS" whose rows did not hold
    # (2^63 itself too: in float64, where NumPy 1.24 compared it with 2^63 - 1, the two are equal)
    for C, b in (([[2 ** 64 - 1, 1, 0]], [5]), ([[1, 1, 0]], [2 ** 64 - 1]), ([[2 ** 63, 1, 0]], [5]),
                 ([[1, 1, 0]], [2 ** 63 + 1])):
        with pytest.raises(ss.InputError, match="below 2\\^63"):
            ss.project(np.array(C, dtype=np.uint64), np.array(b, dtype=np.uint64), [0.0, 0.0, 0.0])
    x, r = ss.project(np.array([[3, 1, 0]], dtype=np.uint64), np.array([5], dtype=np.uint64), [1.0, 1.0, 1.0])
    assert r["status"] == "SUCCESS" and 3 * Fraction(x[0]) + Fraction(x[1]) == 5
    assert r["minimal_change"] and not r["large_change"] and not r["per_row_grids"] and r["input_violation"] > 0


def test_project_infeasible_and_bad_input():
    sp = pytest.importorskip("scipy.sparse")
    C = sp.csr_matrix(np.array([[3]]))
    with pytest.raises(ss.SnapError) as e:
        ss.project(C, [1], [0.3])                 # 3 x = 1 has no double solution
    assert e.value.report["status"] != "SUCCESS"
    with pytest.raises(ValueError):
        ss.project(np.array([[0.5]]), [0], [0.0])  # non-integer C
    with pytest.raises(ValueError):
        ss.project(C, [1, 2], [0.0])               # b of the wrong size


SHARED_FILES = [("cgal-orbifold-generated/bear_orbifold_square_mvc.obj", False),
                ("directional/torus-hex-param.obj", True),
                ("libqex/fandisk_param.obj", False)]


@pytest.mark.parametrize("name,weld", SHARED_FILES)
def test_snap_shared_data(name, weld):
    V, F, UV, FUV = shared_map(name)
    UV2, FUV2, report = ss.snap(V, F, UV, FUV, weld=weld)
    assert report["status"] == "SUCCESS", report["message"]
    bad, cut = seam_violations(V, F, UV2, FUV2, weld=weld)
    assert cut > 0 and bad == 0
    assert ss.is_exactly_seamless(V, F, UV2, FUV2, weld=weld)
    assert report["max_change"] < 1e-5
    # two threads: the same bits
    UV3, FUV3, report3 = ss.snap(V, F, UV, FUV, weld=weld, threads=2)
    assert UV3.tobytes() == UV2.tobytes() and np.array_equal(FUV3, FUV2) and report3["nodes"] == report["nodes"]
    with pytest.raises(ss.InputError):
        ss.snap(V, F, UV, FUV, weld=weld, threads=-1)


# ---- tracing (motorcycle graph, isolines) ----

def axis_parallel_exactly(trace):
    """Every segment of the trace runs along its direction in its face's chart, exactly (Fractions):
    +u/-u keep v, +v/-v keep u, and the other coordinate moves the right way."""
    for (a, b), d in zip(trace["uv_exact"], trace["directions"]):
        keep, move, sign = (1, 0, 1 if d == 0 else -1) if d in (0, 2) else (0, 1, 1 if d == 1 else -1)
        if a[keep] != b[keep] or sign * (b[move] - a[move]) <= 0:
            return False
    return True


def test_trace_isoline_cut_grid():
    V, F, UV, FUV = cut_grid()
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV)
    # from vertex 0 = (0, 0, 0) up the left border: through the cut (a quarter turn) to (0, 1, 0)
    t = ss.trace_isoline(V, F, UV2, FUV2, 0, 0, "+v")
    assert t["status"] == "SUCCESS" and t["end"] == "border" and not t["failure"]
    assert t["start"] == 0 and t["inexact_transfers"] == 0
    assert len(t["faces"]) == 8 and t["points"].shape == (9, 3)
    assert np.array_equal(t["points"], np.array([[0.0, j / 8, 0.0] for j in range(9)]))   # the grid's vertices (exact)
    assert list(t["directions"]) == [1] * 4 + [2] * 4      # +v below the cut, -u in the rotated chart above it
    assert axis_parallel_exactly(t)
    assert 0 in F[t["start_face"]] and t["start_face"] == t["faces"][0]
    for seg, f in zip(t["uv_exact"], t["faces"]):           # the points lie in the UV triangle of their face
        lo, hi = UV2[FUV2[f]].min(axis=0), UV2[FUV2[f]].max(axis=0)
        assert all(lo[c] <= float(p[c]) <= hi[c] for p in seg for c in range(2))
    # the noisy input: the same isoline misses the cut's vertices (inexact transfers), more and shorter pieces
    t0 = ss.trace_isoline(V, F, UV, FUV, 0, 0, "+v")
    assert t0["end"] == "border" and t0["inexact_transfers"] > 0 and len(t0["faces"]) > 8
    # along -v there is no sector at the border vertex; a bad face or direction is refused
    assert ss.trace_isoline(V, F, UV2, FUV2, 0, 0, "-v")["end"] == "invalid_start"
    with pytest.raises(ss.InputError, match="not a row of F"):
        ss.trace_isoline(V, F, UV2, FUV2, len(F), 0, "+u")
    bad = UV2.copy()
    bad[0, 0] = np.nan
    assert ss.trace_isoline(V, F, bad, FUV2, 0, 0, "+u")["status"] == "INVALID_INPUT"



def test_trace_isoline_through_collapsed_face():
    # A flat 3 x 3 grid, UV = (x, y), whose triangle (1, 6, 5) is split at m = (1.5, 1), lifted in 3D, on its side 5-6:
    # the zero-area face (5, m, 6) with three distinct corners, its long side 5-6, the limit of a thin positive
    # triangle whose middle corner m lies just below that side. From m, -u ended with folded_face (the ray along the
    # line was given to the zero-area face) while +u ended at the border; +v crossed the face without a segment, so
    # its polyline started on the long side, not at m; from the face's end corners 5 (+u) and 6 (-u) the end depended
    # on the corner given (folded_face from the corner whose wedge is next to the face's wedge of zero width).
    V, F, UV = flat_grid_scaled(4, scale=1.0)
    m = len(V)
    V = np.vstack([V, [1.5, 1.0, 0.3]])
    UV = np.vstack([UV, [1.5, 1.0]])
    F = np.vstack([[f for f in F if sorted(f) != [1, 5, 6]], [[1, 6, m], [1, m, 5], [5, m, 6]]])
    assert ss.is_exactly_seamless(V, F, UV, F)
    ends = {}
    for v, direction in [(m, d) for d in range(4)] + [(5, 0), (6, 2)]:
        for f, c in zip(*np.nonzero(F == v)):              # every corner of v gives the same trace
            t = ss.trace_isoline(V, F, UV, F, f, c, direction)
            key = (v, direction)
            got = (t["end"], t["message"], list(t["faces"]), t["points"].tolist())
            assert ends.setdefault(key, got) == got, (key, f, c)
            assert not t["failure"] and t["end"] == "border"
            assert len(t["faces"]) == t["faces_crossed"] and np.array_equal(t["points"][0], V[v])
    # along the line from m both ways through the positive faces beside it, to the border vertices (0, 1) and (3, 1)
    assert ends[(m, 2)][3] == [[1.5, 1.0, 0.3], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
    assert ends[(m, 0)][3] == [[1.5, 1.0, 0.3], [2.0, 1.0, 0.0], [3.0, 1.0, 0.0]]
    # across the line: the first segment crosses the zero-area face, from m to the point (1.5, 1) of its long side
    up = ends[(m, 1)]
    assert up[2][0] == len(F) - 1 and up[3][:2] == [[1.5, 1.0, 0.3], [1.5, 1.0, 0.0]] and up[3][-1] == [1.5, 3.0, 0.0]

def test_keyword_values_out_of_range():
    # values the C++ types cannot take, or NaN tolerances: InputError naming the keyword (a TypeError of the bindings
    # before, and rotation_tolerance=nan made an exact map "not quarter-turn seamless")
    V, F, UV, FUV = cut_grid()
    for kwargs, name in (({"max_faces": -1}, "max_faces"), ({"max_faces": 2 ** 64}, "max_faces"),
                         ({"rotation_tolerance": float("nan")}, "rotation_tolerance"),
                         ({"rotation_tolerance": -1.0}, "rotation_tolerance")):
        with pytest.raises(ss.InputError, match=name):
            ss.motorcycle_graph(V, F, UV, FUV, **kwargs)
        with pytest.raises(ss.InputError, match=name):
            ss.trace_isoline(V, F, UV, FUV, 0, 0, "+u", **kwargs)
    with pytest.raises(ss.InputError, match="face"):
        ss.trace_isoline(V, F, UV, FUV, 2 ** 70, 0, "+u")
    # a ray that leaves the surface at a border vertex: the message names the direction (it printed a count of 0)
    t = ss.trace_isoline(V, F, UV, FUV, 0, 0, 2)
    assert t["end"] == "invalid_start" and t["message"].endswith("the start direction 2 (a border vertex: the ray leaves the surface)")
    with pytest.raises(ss.InputError, match="delta_margin_bits"):
        ss.project(np.array([[1, 1]]), [1], [0.5, 0.5], delta_margin_bits=2 ** 40)


def test_motorcycle_graph_cut_grid():
    V, F, UV, FUV = cut_grid()
    g0 = ss.motorcycle_graph(V, F, UV, FUV)
    assert g0["status"] == "SUCCESS" and g0["counts"]["cones"] == 0 and g0["counts"]["border_corners"] == 4
    assert g0["counts"]["inexact_transfers"] > 0          # the tracer sees the noise at the cut
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV)
    g = ss.motorcycle_graph(V, F, UV2, FUV2)
    assert g["status"] == "SUCCESS" and not g["seeded"]
    c = g["counts"]
    # a square: 4 convex border corners (quarter-turn fans) emit no rays; no cone
    assert c == {"separatrices": 0, "failed": 0, "cones": 0, "border_corners": 4, "cones_with_wrong_ray_count": 0,
                 "inexact_transfers": 0}
    assert sum(g["ends"].values()) == 0 and g["separatrices"] == []
    bad = UV2.copy()
    bad[0, 0] = np.inf
    g = ss.motorcycle_graph(V, F, bad, FUV2)
    assert g["status"] == "INVALID_INPUT" and "not finite" in g["message"] and "separatrices" not in g


def flat_torus(n=4, noise=0.0, seed=2):
    """A flat n x n torus: each vertex (i, j) once, seams where the grid wraps (translations by n), corners
    perturbed by `noise`. No cone, no border."""
    rng = random.Random(seed)
    V = [[float(i), float(j), 0.0] for j in range(n) for i in range(n)]
    F, FUV, UV = [], [], []
    for j in range(n):
        for i in range(n):
            I, J = (i, i + 1, i + 1, i), (j, j, j + 1, j + 1)
            for tri in ((0, 1, 2), (0, 2, 3)):
                F.append([(J[c] % n) * n + I[c] % n for c in tri])
                ts = []
                for c in tri:
                    UV.append([I[c] + rng.uniform(-noise, noise), J[c] + rng.uniform(-noise, noise)])
                    ts.append(len(UV) - 1)
                FUV.append(ts)
    return np.array(V), np.array(F), np.array(UV), np.array(FUV)


def test_motorcycle_graph_flat_cylinder():
    # a flat cylinder (wrapping in u, straight aligned borders at v = 0 and v = 3): no cone and no border corner, so four
    # seeded traces. They started at the first corner of the mesh, a border vertex, where the -v ray leaves the surface:
    # invalid_start, one failed trace on an exact map; now they start at an interior vertex
    n, m = 4, 3
    V = np.array([[float(i), float(j), 0.0] for j in range(m + 1) for i in range(n)])
    F, FUV, UV = [], [], []
    for j in range(m):
        for i in range(n):
            I, J = (i, i + 1, i + 1, i), (j, j, j + 1, j + 1)
            for tri in ((0, 1, 2), (0, 2, 3)):
                F.append([J[c] * n + I[c] % n for c in tri])
                FUV.append(list(range(len(UV), len(UV) + 3)))
                UV.extend([[float(I[c]), float(J[c])] for c in tri])
    F, UV, FUV = np.array(F), np.array(UV), np.array(FUV)
    assert ss.is_exactly_seamless(V, F, UV, FUV)
    g = ss.motorcycle_graph(V, F, UV, FUV)
    assert g["seeded"] and g["counts"]["separatrices"] == 4 and g["counts"]["failed"] == 0
    assert all(V[s["start"]][1] not in (0, m) for s in g["separatrices"]) and g["layout"]["valid"]


def test_motorcycle_graph_flat_torus():
    V, F, UV, FUV = flat_torus()
    assert ss.is_exactly_seamless(V, F, UV, FUV)
    g = ss.motorcycle_graph(V, F, UV, FUV)
    assert g["status"] == "SUCCESS" and g["seeded"] and g["counts"]["cones"] == 0
    assert g["counts"]["separatrices"] == 4 and g["counts"]["failed"] == 0
    assert [s["source"] for s in g["separatrices"]] == ["seed"] * 4
    # the seeds advance together and meet each other (or close)
    ends = [s["end"] for s in g["separatrices"]]
    assert all(e in ("closed_loop", "earlier_trace") for e in ends)
    assert all(0 <= s["hit_trace"] < 4 for s in g["separatrices"] if s["end"] == "earlier_trace")
    # the layout: the torus cut along the two loops through the seed is one square patch
    lay = g["layout"]
    assert lay["status"] == "SUCCESS" and lay["valid"] and lay["patches"] == 1 and lay["quad_patches"] == 1
    assert lay["euler_characteristic"] == lay["surface_euler_characteristic"] == 0
    # the same map scaled by 2^600 and 2^-600 (exact): the same layout (the corner angles' exact products overflowed or
    # underflowed in double, and the patches were no longer quads)
    for j in (600, -600):
        lj = ss.motorcycle_graph(V, F, UV * 2.0 ** j, FUV)["layout"]
        assert lj["valid"] and lj["patches"] == 1 and lj["quad_patches"] == 1, (j, lj)
    assert g["trace_ms"] > 0 and all(lay[k] > 0 for k in ("subdivision_ms", "mesh_ms", "measure_ms"))   # the phases ran
    for s in g["separatrices"]:
        assert s["inexact_transfers"] == 0
        assert axis_parallel_exactly(s)
    # without the exact points: the same graph, the same rounded points, no "uv_exact"
    gf = ss.motorcycle_graph(V, F, UV, FUV, exact_uv=False)
    assert gf["counts"] == g["counts"] and gf["layout"]["patches"] == lay["patches"]
    for s, t in zip(g["separatrices"], gf["separatrices"]):
        assert "uv_exact" not in t and np.array_equal(s["uv"], t["uv"]) and s["end"] == t["end"]
    # +u from a vertex of the torus closes after n edges, exactly at its start
    t = ss.trace_isoline(V, F, UV, FUV, 0, 0, "+u")
    assert t["end"] == "closed_loop" and len(t["faces"]) == 4 and np.array_equal(t["points"][0], t["points"][-1])
    t = ss.trace_isoline(V, F, UV, FUV, 0, 0, "+u", max_faces=2)
    assert t["end"] == "length_limit" and not t["failure"] and len(t["faces"]) < 4
    assert t["message"] == "stopped after 2 face crossings, the limit (max_faces)"       # (it was empty)
    with pytest.raises(ss.InputError, match=r"face 0 is not a row of F \(F has none\)"):   # (it said "0..-1")
        ss.trace_isoline(V, F[:0], UV, FUV[:0], 0, 0, "+u")
    g = ss.motorcycle_graph(V, F, UV, FUV, max_faces=1)   # the seeds meet head-on after 2 faces: cut off before
    assert g["ends"]["length_limit"] >= 1 and g["ends"]["closed_loop"] == 0
    # with noise the seams are inexact and the tracer notices; snapped, it is exact again
    Vn, Fn, UVn, FUVn = flat_torus(noise=1e-10)
    gn = ss.motorcycle_graph(Vn, Fn, UVn, FUVn)
    assert gn["status"] == "SUCCESS" and gn["counts"]["inexact_transfers"] > 0 and gn["counts"]["failed"] > 0
    assert "closed_loop" not in [s["end"] for s in gn["separatrices"]]     # the noisy isolines never close
    UV2, FUV2, _ = ss.snap(Vn, Fn, UVn, FUVn)
    g2 = ss.motorcycle_graph(Vn, Fn, UV2, FUV2)
    assert g2["counts"]["failed"] == 0 and g2["counts"]["inexact_transfers"] == 0 and g2["seeded"]
    assert all(s["end"] in ("closed_loop", "earlier_trace") for s in g2["separatrices"])
    assert g2["layout"]["valid"] and g2["layout"]["quad_patches"] == g2["layout"]["patches"]


def quarter_turns_at_interior_vertices(F, UV, FUV):
    """{vertex: n} for every interior vertex whose UV angle sum is n quarter turns, n != 4 (a cone); the
    angles in floating point (the sums of exactly seamless maps are multiples of a quarter turn up to rounding)."""
    edges = {}
    angle = {}
    for f in range(len(F)):
        for k in range(3):
            a, b = F[f][k], F[f][(k + 1) % 3]
            edges[(a, b)] = edges.get((a, b), 0) + 1
            p, q, r = UV[FUV[f][k]], UV[FUV[f][(k + 1) % 3]], UV[FUV[f][(k + 2) % 3]]
            e1, e2 = q - p, r - p
            angle[a] = angle.get(a, 0.0) + abs(np.arctan2(e1[0] * e2[1] - e1[1] * e2[0], e1 @ e2))
    border = {v for (a, b) in edges if (b, a) not in edges for v in (a, b)}
    turns = {v: int(round(s / (np.pi / 2))) for v, s in angle.items() if v not in border}
    return {v: n for v, n in turns.items() if n != 4}


@pytest.mark.parametrize("name,weld", [("cgal-orbifold-generated/bear_orbifold_square_mvc.obj", False),
                                       ("directional/torus-hex-param.obj", True)])
def test_motorcycle_graph_shared_data(name, weld):
    V, F, UV, FUV = shared_map(name)
    g0 = ss.motorcycle_graph(V, F, UV, FUV, weld=weld)
    assert g0["status"] == "SUCCESS"
    assert g0["counts"]["inexact_transfers"] > 0           # the solver's error at the cuts, seen by the tracer
    UV2, FUV2, report = ss.snap(V, F, UV, FUV, weld=weld)
    assert report["status"] == "SUCCESS" and report["flips_after"] == 0
    g = ss.motorcycle_graph(V, F, UV2, FUV2, weld=weld)
    c = g["counts"]
    assert g["status"] == "SUCCESS" and c["failed"] == 0 and c["inexact_transfers"] == 0
    assert c["cones_with_wrong_ray_count"] == 0 and c["separatrices"] == len(g["separatrices"])
    assert sum(g["ends"].values()) == c["separatrices"]
    for s in g["separatrices"]:
        assert s["end"] in ("cone", "border", "earlier_trace") or (g["seeded"] and s["end"] == "closed_loop")
        assert axis_parallel_exactly(s)
        if s["end"] == "earlier_trace":
            assert 0 <= s["hit_trace"] < c["separatrices"]
    # vertices by position (a cut mesh's duplicated vertices are one vertex when welded)
    key = {}
    Fw = np.array([[key.setdefault(tuple(V[v]) if weld else v, len(key)) for v in row] for row in F])
    position = {i: tuple(V[k]) if not weld else k for k, i in key.items()}
    cones = {position[v]: n for v, n in quarter_turns_at_interior_vertices(Fw, UV2, FUV2).items()}
    start_key = lambda s: tuple(V[s["start"]])
    # the cone rule, checked from the UVs here: a cone of n quarter turns emits n rays
    assert c["cones"] == len(cones)
    rays = {}
    for s in g["separatrices"]:
        if s["source"] == "cone":
            rays[start_key(s)] = rays.get(start_key(s), 0) + 1
    assert rays == cones
    assert g["seeded"] == (len(cones) == 0 and c["border_corners"] == 0)


def test_tracing_refuses_a_map_that_is_not_quarter_turn_seamless():
    V, F, UV, FUV = cut_grid()
    upper = np.unique(FUV[len(F) // 2:])                    # the rotated half, turned by another 45 degrees
    UV = UV.copy()
    UV[upper] = UV[upper] @ (np.array([[1.0, -1.0], [1.0, 1.0]]) / np.sqrt(2)).T
    g = ss.motorcycle_graph(V, F, UV, FUV)
    assert g["status"] == "NOT_QUARTER_TURN_SEAMLESS" and "45 degrees" in g["message"] and "separatrices" not in g
    t = ss.trace_isoline(V, F, UV, FUV, 0, 0, "+u")
    assert t["status"] == "NOT_QUARTER_TURN_SEAMLESS" and "end" not in t
    # a rotation tolerance above 45 degrees lets the tracer read it; the traces then fail at the cut
    g = ss.motorcycle_graph(V, F, UV, FUV, rotation_tolerance=46.0)
    assert g["status"] == "SUCCESS" and g["counts"]["failed"] > 0 and g["counts"]["inexact_transfers"] > 0


# ---- OBJ files and input checks ----

def bits(a):
    """The bits of a float64 array (np.array_equal would take -0.0 for 0.0)."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def test_read_obj_write_obj(tmp_path):
    V, F, UV, FUV = cut_grid()
    V = V.copy()
    V[1, 2] = -0.0                                         # kept apart from 0.0, bit for bit
    UV = UV.copy()
    UV[2] = [5e-324, 1.7976931348623157e308]               # extreme doubles survive the text
    path = tmp_path / "grid.obj"
    assert "wrote 128 faces" in ss.write_obj(path, V, F, UV, FUV)
    V2, F2, UV2, FUV2 = ss.read_obj(path)
    assert np.array_equal(bits(V2), bits(V)) and np.array_equal(bits(UV2), bits(UV))
    assert np.array_equal(F2, F) and np.array_equal(FUV2, FUV) and F2.shape == (128, 3) and V2.shape == (81, 3)
    # the same arrays as an independent parse of the file
    Vp, Fp, UVp, FUVp = parse_obj(path)
    assert np.array_equal(bits(Vp), bits(V2)) and np.array_equal(bits(UVp), bits(UV2))
    assert np.array_equal(Fp, F2) and np.array_equal(FUVp, FUV2)


def test_read_obj_weld(tmp_path):
    # a cut mesh: one v per face corner (vertices duplicated, as libigl/Directional write them)
    V, F, UV, FUV = cut_grid()
    path = tmp_path / "cut.obj"
    ss.write_obj(path, V[F].reshape(-1, 3), np.arange(3 * len(F)).reshape(-1, 3), UV, FUV)
    Vc, Fc, _, _ = ss.read_obj(path)
    assert len(Vc) == 3 * len(F)
    Vw, Fw, UVw, FUVw = ss.read_obj(path, weld=True)
    assert len(Vw) == len(V) and len({tuple(p) for p in Vw}) == len(V)     # one row per position
    assert np.array_equal(Vw[Fw], V[F]) and np.array_equal(UVw, UV) and np.array_equal(FUVw, FUV)
    # welded, the seams are visible again: the same cut edges as the original grid's, snapped exactly
    assert not ss.is_exactly_seamless(Vw, Fw, UVw, FUVw)
    UV2, FUV2, report = ss.snap(Vw, Fw, UVw, FUVw)
    assert report["cut_edges"] == ss.snap(V, F, UV, FUV)[2]["cut_edges"] > 0 and ss.is_exactly_seamless(Vw, Fw, UV2, FUV2)


def test_read_obj_threads(tmp_path):
    # a file of more than 4 MiB is parsed in two halves with threads=2: the same matrices, bit for bit, and the same
    # message for an error in its second half
    V, F, UV, FUV = cut_grid(n=160, noise=1e-9)
    path = tmp_path / "big.obj"
    ss.write_obj(path, V, F, UV, FUV)
    assert os.path.getsize(path) > 4 << 20
    one, two = ss.read_obj(path, threads=1), ss.read_obj(path, threads=2)
    for a, b in zip(one, two):
        assert a.dtype == b.dtype and a.shape == b.shape
        assert np.array_equal(bits(a), bits(b)) if a.dtype == np.float64 else np.array_equal(a, b)
    bad = tmp_path / "bad_big.obj"
    lines = path.read_text().splitlines()
    lines[-10] = "f 1/1 2/2"
    bad.write_text("\n".join(lines) + "\n")
    messages = []
    for threads in (1, 2):
        with pytest.raises(ss.InputError) as e:
            ss.read_obj(bad, threads=threads)
        messages.append(str(e.value))
    assert messages[0] == messages[1] and ":%d: face with 2 vertices" % (len(lines) - 9) in messages[0]
    with pytest.raises(ss.InputError, match="threads must be in"):
        ss.read_obj(path, threads=-1)


def test_obj_errors(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 4/1\n")
    with pytest.raises(ss.InputError) as e:
        ss.read_obj(bad)
    assert str(e.value).startswith("%s:5: vertex index 4 out of range" % bad)
    assert isinstance(e.value, ValueError)
    with pytest.raises(ss.InputError, match="cannot open"):
        ss.read_obj(tmp_path / "missing.obj")
    V, F, UV, FUV = cut_grid()
    out = tmp_path / "out.obj"
    UVn = UV.copy()
    UVn[3, 1] = np.nan
    with pytest.raises(ss.InputError, match=r"UV\(3, 1\) is not finite"):
        ss.write_obj(out, V, F, UVn, FUV)
    Fo = F.copy()
    Fo[2, 1] = len(V)
    with pytest.raises(ss.InputError, match="face 2 has an index out of range"):
        ss.write_obj(out, V, Fo, UV, FUV)
    with pytest.raises(ss.InputError, match="cannot"):
        ss.write_obj(tmp_path / "no_such_dir" / "out.obj", V, F, UV, FUV)
    with pytest.raises(ss.InputError, match="F has no face"):   # it wrote a file that read_obj refuses
        ss.write_obj(out, V, F[:0], UV, FUV[:0])
    assert not out.exists() and list(tmp_path.iterdir()) == [bad]          # nothing written, no temporary left


def test_obj_text_after_coordinates(tmp_path):
    # only numbers may follow a record's coordinates (w, a color); other text was ignored, and a file with carriage
    # returns alone as line ends was read as one line: its first vertex, the rest ignored
    tail = "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"
    ok = tmp_path / "ok.obj"
    ok.write_text("v 0 0 0 1 0.5 0.25  # a color\nv 1 0 0 1\nv 0 1 0\n" + tail)
    V, F, UV, FUV = ss.read_obj(ok)
    assert V.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]] and len(F) == 1
    lines = "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + tail
    cr = lambda text: text.replace("\n", "\r")                 # carriage returns alone as line ends
    for name, text, refusal in [
            ("junk.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0 junk\n" + tail,
             r"junk.obj:3: unexpected text 'junk' after the coordinates of a 'v' record"),
            ("cr.obj", cr(lines), r"cr.obj:1: unexpected text 'v' .*carriage return alone"),
            # the whole file one comment (it had no hint)
            ("cr_comment.obj", cr("# an exporter's header\n" + lines),
             r"cr_comment.obj: empty mesh: no face in 1 lines .*carriage return alone"),
            ("huge.obj", "v 0 0 0 1e999\n" + lines[8:],
             r"huge.obj:1: number '1e999' after .* outside the range of double")]:
        (tmp_path / name).write_bytes(text.encode())
        with pytest.raises(ss.InputError, match=refusal):
            ss.read_obj(tmp_path / name)
    crlf = tmp_path / "crlf.obj"
    crlf.write_bytes(lines.replace("\n", "\r\n").encode())
    assert np.array_equal(ss.read_obj(crlf)[0], V)


def test_index_arrays_must_hold_integers():
    V, F, UV, FUV = cut_grid()
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV)
    # integral floats are integers (SciPy and NumPy arithmetic make them): the same result, bit for bit
    UVf, FUVf, _ = ss.snap(V, F.astype(float), UV, FUV.astype(float))
    assert np.array_equal(bits(UVf), bits(UV2)) and np.array_equal(FUVf, FUV2)
    with pytest.raises(ss.InputError) as e:                                # used to be truncated to F silently
        ss.snap(V, F.astype(float) + 0.5, UV, FUV)
    assert str(e.value) == "F must hold integers (row indices of V); F[0, 0] = 0.5 is not one"
    Fn = F.astype(float)
    Fn[4, 2] = np.nan
    with pytest.raises(ss.InputError, match=r"FUV\[4, 2\] = nan is not one"):
        ss.is_exactly_seamless(V, F, UV, Fn)
    Fn[4, 2] = 2.0 ** 62                                                    # integral, but beyond int64's safe range
    with pytest.raises(ss.InputError, match=r"FUV\[4, 2\] = 4.6\d+e\+18 is 2\^62 or more"):
        ss.is_exactly_seamless(V, F, UV, Fn)
    with pytest.raises(ss.InputError, match="not values of type bool"):
        ss.motorcycle_graph(V, F > 0, UV, FUV)
    with pytest.raises(ss.InputError, match="row indices of UV"):
        ss.write_obj("never_written.obj", V, F, UV, FUV + 0.25)
    with pytest.raises(ss.InputError, match="C must hold integers"):
        ss.project(np.array([[0.5]]), [0], [0.0])


def test_trace_isoline_refuses_unknown_directions():
    V, F, UV, FUV = cut_grid()
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV)
    for d in ("+w", "u", 4, -1, 1.0, True, None):
        with pytest.raises(ss.InputError) as e:
            ss.trace_isoline(V, F, UV2, FUV2, 0, 0, d)
        assert str(e.value) == "unknown direction %r: the directions are '+u', '+v', '-u', '-v' (or 0, 1, 2, 3)" % (d,)
    assert ss.trace_isoline(V, F, UV2, FUV2, 0, 0, np.int64(1))["end"] == ss.trace_isoline(V, F, UV2, FUV2, 0, 0, "+v")["end"]
    with pytest.raises(ss.InputError, match="face must be an integer, got 0.5"):
        ss.trace_isoline(V, F, UV2, FUV2, 0.5, 0, "+u")
    with pytest.raises(ss.InputError, match="corner 3 is not 0, 1 or 2"):
        ss.trace_isoline(V, F, UV2, FUV2, 0, 3, "+u")


# ---- quad meshes ----

def check_quad_mesh(V, F, UV, FUV, QV, QF, report, grid_scale=1.0, closed=True):
    """The quad mesh against the map, here in Fractions: every quad vertex's integer UV maps back exactly into the
    closed UV triangle of its face (onto the corner of its vertex at location 0), every edge of a closed mesh is in
    exactly two quads, V - E + F is the map's, and there are as many quads as the map's exact UV area."""
    assert report["status"] == "SUCCESS" and QF.shape[1] == 4 and QV.shape == (len(report["QV_face"]), 3)
    S = Fraction(grid_scale)
    area = Fraction(0)
    for f in range(len(F)):
        a, b, c = (tuple(Fraction(x) for x in UV[FUV[f][k]]) for k in range(3))
        area += ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2
    assert report["uv_area"] == str(area * S * S) and len(QF) == area * S * S
    for i in range(len(QV)):
        f = report["QV_face"][i]
        p = tuple(Fraction(int(x)) / S for x in report["QV_uv"][i])
        t = [tuple(Fraction(x) for x in UV[FUV[f][k]]) for k in range(3)]
        sides = [(t[(k + 1) % 3][0] - t[k][0]) * (p[1] - t[k][1]) - (t[(k + 1) % 3][1] - t[k][1]) * (p[0] - t[k][0])
                 for k in range(3)]
        assert all(s >= 0 for s in sides)
        location = report["QV_location"][i]
        assert (location == 0) == (sides.count(0) == 2) and (location == 2) == (sides.count(0) == 0)
        if location == 0:
            k = [F[f][k] for k in range(3) if t[k] == p]
            assert len(k) == 1 and np.array_equal(V[k[0]], V[report["QV_vertex"][i]]) and np.array_equal(QV[i], V[k[0]])
    edges = {}
    for q in QF:
        for k in range(4):
            e = (min(q[k], q[(k + 1) % 4]), max(q[k], q[(k + 1) % 4]))
            edges[e] = edges.get(e, 0) + 1
    assert all(n == 2 for n in edges.values()) == closed and all(n <= 2 for n in edges.values())
    assert len(QV) - len(edges) + len(QF) == report["euler_characteristic"] == report["input_euler_characteristic"]
    assert report["irregular_vertices"] == report["cones"] and report["covers_map"]
    assert all(len(c) > 0 for c in report["QF_faces"])
    # the patches: rectangles of quads covering the mesh, every quad a cell of its patch's grid, each cell once, and
    # each grid point of a patch one vertex (read from the corner ranks)
    patches = report["patches"]
    assert patches["status"] == "SUCCESS" and patches["all_rectangles"] and len(patches["sizes"]) == patches["patches"]
    assert sum(w * h for w, h in patches["sizes"]) == len(QF) == len(report["QF_patch"])
    cells, grid = set(), {}
    for q in range(len(QF)):
        p, (i, j), k = report["QF_patch"][q], report["QF_patch_cell"][q], report["QF_patch_corner"][q]
        w, h = patches["sizes"][p]
        assert 0 <= i < w and 0 <= j < h and (p, i, j) not in cells
        cells.add((p, i, j))
        for t, (di, dj) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
            assert grid.setdefault((p, i + di, j + dj), QF[q][(k + t) % 4]) == QF[q][(k + t) % 4]
    grids = ss.patch_vertex_grids(QF, report)               # the same grid points as arrays
    assert all(grids[p][j, i] == v for (p, i, j), v in grid.items())
    assert all(g.shape == (h + 1, w + 1) and (g >= 0).all() for g, (w, h) in zip(grids, patches["sizes"]))


def test_extract_quad_mesh_generated():
    V, F, UV, FUV = flat_torus(n=4)                       # exact as generated
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV)
    check_quad_mesh(V, F, UV, FUV, QV, QF, r)
    assert len(QF) == 16 and r["euler_characteristic"] == 0 and r["irregular_vertices"] == 0
    QV2, QF2, r2 = ss.extract_quad_mesh(V, F, UV / 4, FUV, grid_scale=4.0)    # scale covariance, bit for bit
    assert np.array_equal(QV2, QV) and np.array_equal(QF2, QF) and np.array_equal(r2["QV_uv"], r["QV_uv"])
    # the cut grid snapped to an integer-grid map: its border lies on integer isolines, so every cell is complete
    Vc, Fc, UVc, FUVc = cut_grid(n=8, noise=1e-9, size=8.0, t=(3.0, 1.0))
    UV2, FUV2, _ = ss.snap(Vc, Fc, UVc, FUVc, integer_grid_map=True)
    QV, QF, r = ss.extract_quad_mesh(Vc, Fc, UV2, FUV2, grid_scale=2.0)
    check_quad_mesh(Vc, Fc, UV2, FUV2, QV, QF, r, grid_scale=2.0, closed=False)
    assert len(QF) == 256 and r["boundary_loops"] == 1


def quarter_plane_cone(n, sheets=1):
    """The quarter plane [0, n]^2 with its sides glued ((t, 0) ~ (0, t): cut edges with a quarter turn): a cone of 90
    degrees (valence 1) at (0, 0), row 0 of V; triangles of half a unit, a fan of 4 around the cone. 3D on a paper cone.
    With sheets=2: two such sheets (3D one unit apart) crossing along the ray from (1.5, 0.5) to (n, 0.5), a map wound
    twice around the vertex at (1.5, 0.5) inside the cell [1, 2] x [0, 1], which shares its sides u = 1 with the cells
    of the two cones. Returns V, F, UV, FUV, the rows of the cones and the row of that vertex (None with one sheet)."""
    rows, V, UV, F, FUV = {}, [], [], [], []
    def vertex(i, j, sheet):
        key = ((j, 0) if i == 0 and j > 0 else (i, j)) + (0 if (i, j) == (3, 1) else sheet,)
        if key not in rows:
            r, t = np.hypot(key[0], key[1]) / 2, np.arctan2(key[1], key[0])
            rows[key] = len(V)
            V.append([r / 4 * np.cos(4 * t), r / 4 * np.sin(4 * t), r * np.sqrt(15.0) / 4 + key[2]])
        return rows[key]
    def triangle(sheet, above, *corners):      # below the ray the other sheet's vertices on it
        F.append([vertex(i, j, 1 - sheet if j == 1 and i > 3 and not above and sheets == 2 else sheet) for i, j in corners])
        FUV.append(list(range(len(UV), len(UV) + 3)))
        UV.extend([[i / 2, j / 2] for i, j in corners])
    ring = [(2, 0), (2, 1), (2, 2), (1, 2), (0, 2)]
    for sheet in range(sheets):
        for k in range(4):
            triangle(sheet, k >= 1, (0, 0), ring[k], ring[k + 1])
        for i in range(2 * n):
            for j in range(2 * n):
                if i >= 2 or j >= 2:
                    triangle(sheet, j >= 1, (i, j), (i + 1, j), (i + 1, j + 1))
                    triangle(sheet, j >= 1, (i, j), (i + 1, j + 1), (i, j + 1))
    cones = [rows[(0, 0, sheet)] for sheet in range(sheets)]
    return np.array(V), np.array(F), np.array(UV), np.array(FUV), cones, rows.get((3, 1, 0))


def test_extract_quad_mesh_splits_a_cone_of_90_degrees():
    V, F, UV, FUV, _, _ = quarter_plane_cone(3)
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV)
    UV_before = UV.copy()
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV)
    # 9 cells, the 4 at the cone one quad; 16 integer points less 3 glued and the cone and its two neighbours
    assert len(QF) == 6 and len(QV) == 10 and list(r["split_cones"]) == [0] and r["euler_characteristic"] == 1
    assert 0 not in r["QV_vertex"]                          # the cone is no quad vertex
    sides = [tuple(sorted((a, b))) for q in QF for a, b in zip(q, np.roll(q, -1))]
    uses = {e: sides.count(e) for e in sides}               # 1 on the border, 2 inside
    degree = np.bincount([v for e in uses for v in e], minlength=len(QV))
    border = {v for e, k in uses.items() if k == 1 for v in e}
    assert sorted(degree[v] for v in range(len(QV)) if v not in border) == [3, 3, 3, 4] and r["irregular_vertices"] == 3
    assert Fraction(r["uv_area"]) == 9 and r["quads"] == 9 - 3 and r["covers_map"]
    assert r["patches"]["all_rectangles"]
    with pytest.raises(ss.SnapError) as e:                  # refused without the split, the arrays untouched
        ss.extract_quad_mesh(V, F, UV, FUV, split_valence_one_cones=False)
    assert e.value.report["status"] == "INVALID_INPUT" and "(a cone of valence 1)" in e.value.report["message"]
    assert np.array_equal(UV, UV_before)


def test_extract_quad_mesh_fills_a_cone_cell_with_a_branched_cell():
    # two sheets of the quarter plane wound twice around (1.5, 0.5): the cell of each sheet's 90-degree cone shares a
    # side with the branched cell, and the three become one ladder of 3 quads for their area 4
    V, F, UV, FUV, cones, w = quarter_plane_cone(3, sheets=2)
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV)
    assert sorted(r["absorbed_cones"]) == sorted(cones) and list(r["filled_branch_points"]) == [w]
    assert len(r["split_cones"]) == 0 and not set(cones + [w]) & set(r["QV_vertex"])
    assert Fraction(r["uv_area"]) == 18 and len(QF) == r["quads"] == 17 and r["euler_characteristic"] == 1
    assert r["irregular_vertices"] == 2                     # the rungs end at the cone cells' corners
    assert len(QV) - len({tuple(sorted((a, b))) for q in QF for a, b in zip(q, np.roll(q, -1))}) + len(QF) == 1
    with pytest.raises(ss.SnapError) as e:                  # refused without the fill
        ss.extract_quad_mesh(V, F, UV, FUV, fill_branched_cells=False)
    assert e.value.report["status"] == "INVALID_INPUT"


def branched_disk(center, turns, N=16, rings=10):
    """A disk that the map winds `turns` times around `center` (row 0 of V), one chart, no cut: rings of turns * N
    vertices at radii 0.5 .. rings / 2; in 3D a flat disk whose angle is the UV angle / turns."""
    V, UV, F = [[0.0, 0.0, 0.0]], [list(center)], []
    index = lambda j, k: 1 + (j - 1) * turns * N + k % (turns * N)
    for j in range(1, rings + 1):
        for k in range(turns * N):
            r, t = 0.5 * j, 2 * np.pi * k / N
            V.append([r * np.cos(t / turns), r * np.sin(t / turns), 0.0])
            UV.append([center[0] + r * np.cos(t), center[1] + r * np.sin(t)])
    for k in range(turns * N):
        F.append([0, index(1, k), index(1, k + 1)])
        for j in range(1, rings):
            F += [[index(j, k), index(j + 1, k), index(j + 1, k + 1)], [index(j, k), index(j + 1, k + 1), index(j, k + 1)]]
    F = np.array(F)
    return np.array(V), F, np.array(UV), F.copy()


def test_quad_mesh_in_one_call_generated():
    # quad_mesh() = snap(integer_grid_map=True, ...) + extract_quad_mesh(): on an exact map the snap keeps it, and the quads
    # are extract_quad_mesh()'s; a map whose cone is off the integer points (the quarter plane moved by (0.3, 0.3): its
    # seam translation is not an integer vector) is refused by the snap, said so, and the arrays stay
    V, F, UV, FUV, cones, _ = quarter_plane_cone(3)
    QV, QF, r = ss.quad_mesh(V, F, UV, FUV)
    QV1, QF1, r1 = ss.extract_quad_mesh(V, F, UV, FUV)
    assert np.array_equal(QF, QF1) and np.array_equal(QV, QV1) and list(r["split_cones"]) == cones
    assert r["snap"]["status"] == "SUCCESS" and np.array_equal(r["UV"], UV) and np.array_equal(r["FUV"], FUV)
    moved = UV + 0.3
    before = moved.copy()
    with pytest.raises(ss.SnapError) as e:
        ss.quad_mesh(V, F, moved, FUV)
    assert e.value.report["message"].startswith("snapping failed: ") and e.value.report["snap"]["status"] == "INVALID_INPUT"
    assert np.array_equal(moved, before)
    QV, QF, r = ss.quad_mesh(V, F, moved, FUV, raise_on_failure=False)
    assert QV is None and QF is None and r["status"] == "INVALID_INPUT" and "snap" in r


def test_extract_quad_mesh_fills_a_branched_cell():
    V, F, UV, FUV = branched_disk((0.5, 0.25), 2)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV)
    assert list(r["filled_branch_points"]) == [0] and 0 not in r["QV_vertex"] and r["euler_characteristic"] == 1
    sides = [tuple(sorted((a, b))) for q in QF for a, b in zip(q, np.roll(q, -1))]
    uses = {e: sides.count(e) for e in sides}
    assert all(k in (1, 2) for k in uses.values())           # manifold edges
    degree = np.bincount([v for e in uses for v in e], minlength=len(QV))
    border = {v for e, k in uses.items() if k == 1 for v in e}
    inside = [degree[v] for v in range(len(QV)) if v not in border]
    assert inside.count(5) == 4 and all(d in (4, 5) for d in inside) and r["irregular_vertices"] == 4
    with pytest.raises(ss.SnapError) as e:                  # refused without the fill
        ss.extract_quad_mesh(V, F, UV, FUV, fill_branched_cells=False)
    assert e.value.report["status"] == "INVALID_INPUT" and "branches inside a cell" in e.value.report["message"]


def test_extract_quad_mesh_refusals():
    V, F, UV, FUV = flat_torus(n=4, noise=1e-10)          # not exactly seamless
    with pytest.raises(ss.SnapError) as e:
        ss.extract_quad_mesh(V, F, UV, FUV)
    assert e.value.report["status"] == "INVALID_INPUT" and "integer-grid map" in e.value.report["message"]
    V, F, UV, FUV = flat_torus(n=4)
    UV = UV.copy()
    UV[FUV[F == 5]] = [3.0, 1.0]                           # vertex (1, 1) moved to (3, 1): fold-overs, still an IGM
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV, raise_on_failure=False)
    assert QV is None and QF is None and r["status"] == "FOLD_OVERS" and len(r["fold_overs"]) > 0
    assert "fold-overs" in r["message"]
    assert r["advice"].startswith("untangle the map first") and r["message"].endswith("; " + r["advice"])
    # max_grid_cells: the 32 triangles of the 4 x 4 torus have boxes of one cell each
    V, F, UV, FUV = flat_torus(n=4)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV, max_grid_cells=31, raise_on_failure=False)
    assert QV is None and r["status"] == "RANGE_EXCEEDED" and "max_grid_cells" in r["message"]
    QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV, max_grid_cells=32)
    assert len(QF) == 16 and ss._core.default_max_grid_cells == 2 ** 24
    with pytest.raises(ss.InputError):
        ss.extract_quad_mesh(V, F, UV, FUV, max_grid_cells=-1)


def test_quad_mesh_patches_standalone():
    n = 5                                                  # a grid of n x n quads: one patch, its 4 corners the nodes
    idx = lambda i, j: j * (n + 1) + i
    grid = np.array([[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for j in range(n) for i in range(n)])
    r = ss.quad_mesh_patches(grid)
    assert r["status"] == "SUCCESS" and r["all_rectangles"] and r["nodes"] == 4 and r["motorcycles"] == 0
    assert r["sizes"] == [[n, n]] and sorted(map(tuple, r["QF_patch_cell"])) == [(i, j) for i in range(n) for j in range(n)]
    g = ss.patch_vertex_grids(grid, r)                      # the grid's vertices, row by row, up to the patch's frame
    assert len(g) == 1 and g[0].shape == (n + 1, n + 1) and sorted(g[0].ravel()) == list(range((n + 1) ** 2))
    assert any(np.array_equal(np.rot90(g[0], t), np.arange((n + 1) ** 2).reshape(n + 1, n + 1)) for t in range(4))
    with pytest.raises(ss.InputError, match="the report is of another quad mesh"):   # was a raw IndexError
        ss.patch_vertex_grids(grid[:5], r)
    # the same number of rows, another mesh (the rows reversed): a grid point got two vertices, silently overwritten
    with pytest.raises(ss.InputError, match="puts vertex .* where another row put vertex .* another quad mesh"):
        ss.patch_vertex_grids(grid[::-1], r)
    for not_a_report in [None, {}, ss.quad_layout(grid)]:    # TypeError, KeyError 'status', KeyError 'QF_patch'
        with pytest.raises(ss.InputError, match="report must be the dict of quad_mesh_patches"):
            ss.patch_vertex_grids(grid, not_a_report)
    # the quad mesh of an extracted map: rectangles covering it, as in extract_quad_mesh()'s report
    V, F, UV, FUV = flat_torus(n=4)
    QV, QF, e = ss.extract_quad_mesh(V, F, UV, FUV)
    r = ss.quad_mesh_patches(QF)
    assert r["all_rectangles"] and sum(w * h for w, h in r["sizes"]) == len(QF) == 16
    # refusals: rows that are no quad of a manifold mesh (InputError), a vertex with two fans (INVALID_INPUT)
    for bad in [grid[:, :3], np.array([[0, 1, 1, 2]]), np.array([[0, 1, 2, 3], [0, 1, 4, 5]]), np.array([[0, 1, 2, -3]]),
                grid[np.newaxis]]:                         # 3-D: was a TypeError of the bindings
        with pytest.raises(ss.InputError):
            ss.quad_mesh_patches(bad)
    with pytest.raises(ss.InputError, match="F must be a 2-D array"):
        ss.snap(V, F[np.newaxis], UV, FUV)
    pinched = np.array([[0, 1, 2, 3], [0, 4, 5, 6]])
    with pytest.raises(ss.SnapError) as err:
        ss.quad_mesh_patches(pinched)
    assert err.value.report["status"] == "INVALID_INPUT" and "vertex 0 is not manifold" in err.value.report["message"]
    r = ss.quad_mesh_patches(pinched, raise_on_failure=False)
    assert r["status"] == "INVALID_INPUT" and list(r["QF_patch"]) == [-1, -1]
    # with sparse indices the message names the vertex by its index in QF (it named the mesh's own number, 0)
    for call in (ss.quad_mesh_patches, ss.quad_layout):
        r = call(pinched + 100, raise_on_failure=False)
        message = r["message"] if call is ss.quad_mesh_patches else r["patches"]["message"]
        assert "vertex 100 is not manifold" in message, message
        if call is ss.quad_layout:
            assert "vertex 100 is not manifold" in r["message"], r["message"]


def check_quad_layout(QF, r):
    """the layout report r of quad_layout(QF): a face per patch, each polygon with its patch's 4 corners first at (0, 0)
    and sides between them of width, height, width, height; the Euler characteristic of the quad mesh; LV distinct"""
    QF = np.asarray(QF)
    edges = {tuple(sorted((q[k], q[(k + 1) % 4]))) for q in QF for k in range(4)}
    chi = len(np.unique(QF)) - len(edges) + len(QF)
    assert r["status"] == "SUCCESS" and len(r["LF"]) == r["faces"] == r["patches"]["patches"]
    assert len(r["LV"]) == r["vertices"] == len(set(r["LV"])) and r["euler_characteristic"] == chi
    assert r["vertices"] - r["arcs"] + r["faces"] == chi
    for poly, corner, length, (w, h) in zip(r["LF"], r["LF_corner"], r["LF_length"], r["patches"]["sizes"]):
        assert corner[0] and corner.sum() == 4 and len(poly) == len(corner) == len(length)
        cut = list(np.flatnonzero(corner)) + [len(poly)]
        assert [int(length[cut[k]:cut[k + 1]].sum()) for k in range(4)] == [w, h, w, h]


def test_quad_layout():
    n = 5                                                  # a grid of n x n quads: one face, its 4 corners
    idx = lambda i, j: j * (n + 1) + i
    grid = np.array([[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for j in range(n) for i in range(n)])
    r = ss.quad_layout(grid)
    check_quad_layout(grid, r)
    assert sorted(r["LV"]) == [idx(0, 0), idx(n, 0), idx(0, n), idx(n, n)] and r["border_arcs"] == 4
    assert r["polygon_mesh"] and r["t_junctions"] == 0 and list(r["LF_length"][0]) == [n] * 4
    # sparse vertex indices (e.g. a part of a larger QV): the mesh of the vertices QF uses, LV in QF's numbering (the
    # rows up to the largest index were allocated, 2^30 vertices here, and counted in the Euler characteristic)
    sparse = 2 * grid + 2 ** 30
    r = ss.quad_layout(sparse)
    check_quad_layout(sparse, r)
    assert sorted(r["LV"]) == sorted(2 * np.array([idx(0, 0), idx(n, 0), idx(0, n), idx(n, n)]) + 2 ** 30)
    assert r["euler_characteristic"] == 1
    p = ss.quad_mesh_patches(sparse)
    assert p["sizes"] == [[n, n]] and p["nodes"] == 4
    assert np.array_equal(ss.patch_vertex_grids(sparse, p)[0], 2 * ss.patch_vertex_grids(grid, ss.quad_mesh_patches(grid))[0] + 2 ** 30)
    # an L of three n x n blocks: the reflex corner (3 quads) sends traces to the border, which cut it into 3 squares
    jdx = lambda i, j: j * (2 * n + 1) + i
    ell = np.array([[jdx(i, j), jdx(i + 1, j), jdx(i + 1, j + 1), jdx(i, j + 1)]
                    for j in range(2 * n) for i in range(2 * n) if i < n or j < n])
    r = ss.quad_layout(ell)
    check_quad_layout(ell, r)
    assert r["faces"] == 3 and r["patches"]["sizes"] == [[n, n]] * 3 and r["t_junctions"] == 0
    corners = [(0, 0), (n, 0), (2 * n, 0), (0, n), (n, n), (2 * n, n), (0, 2 * n), (n, 2 * n)]
    assert sorted(r["LV"]) == sorted(jdx(i, j) for i, j in corners)
    # the flat torus (no node: traces from its first vertex close up): its two loops split at their middle
    V, F, UV, FUV = flat_torus(n=4)
    QV, QF, e = ss.extract_quad_mesh(V, F, UV, FUV)
    r = ss.quad_layout(QF)
    check_quad_layout(QF, r)
    assert r["faces"] == 1 and r["euler_characteristic"] == 0 and not r["polygon_mesh"] and r["non_simple_faces"] == 1
    with pytest.raises(ss.SnapError):
        ss.quad_layout(np.array([[0, 1, 2, 3], [0, 4, 5, 6]]))
    with pytest.raises(ss.InputError):
        ss.quad_layout(grid[:, :3])


def unit_cube():
    """The surface of the unit cube, each square side a chart of its own (the unit square at (2 s, 0) for side s),
    two triangles per side: an exact integer-grid map whose 8 corners are cones of 3 quarter turns."""
    sides = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, 0, 0), (0, 0, 1), (0, 1, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    F, UV, FUV = [], [], []
    for s, (o, a, b) in enumerate(sides):                   # a x b is the outward normal
        square = [(0, 0), (1, 0), (1, 1), (0, 1)]
        corner = [tuple(o[c] + i * a[c] + j * b[c] for c in range(3)) for i, j in square]
        index = [x + 2 * y + 4 * z for x, y, z in corner]
        for tri in ((0, 1, 2), (0, 2, 3)):
            F.append([index[k] for k in tri])
            FUV.append([len(UV) + k for k in range(3)])
            UV.extend([2 * s + square[k][0], square[k][1]] for k in tri)
    V = [[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    return np.array(V, dtype=float), np.array(F), np.array(UV, dtype=float), np.array(FUV)


def test_trace_isoline_at_a_cone_in_the_chart_of_the_face():
    # every corner of the cube is a cone of 3 quarter turns; a side's two triangles are one chart. A direction that the
    # chart shows at the corner (along the side's edges, +u / +v at its corner (0, 0), ...) is the same ray from either
    # triangle (from the second triangle, +u at (0, 0), along an edge of the first, was invalid_start: turning
    # counter-clockwise from its corner the cone closes before reaching it); the others follow the counter-clockwise rule
    # from either triangle alike (the two triangles' corners at a vertex span consecutive angles of one chart)
    V, F, UV, FUV = unit_cube()
    shown = {(0, 0): ("+u", "+v"), (1, 0): ("-u", "+v"), (1, 1): ("-u", "-v"), (0, 1): ("+u", "-v")}
    def ray(f, c, d):
        t = ss.trace_isoline(V, F, UV, FUV, f, c, d)
        return t["end"], tuple(t["points"][1]) if len(t["points"]) > 1 else None
    for side in range(6):
        a, b = 2 * side, 2 * side + 1
        for ca, v in enumerate(F[a]):
            if v not in F[b]:
                continue
            cb = list(F[b]).index(v)
            local = tuple(int(x) for x in UV[FUV[a][ca]] - (2 * side, 0))
            for d in ("+u", "+v", "-u", "-v"):
                assert ray(a, ca, d) == ray(b, cb, d), (side, v, d)
                if d in shown[local]:
                    end, point = ray(a, ca, d)
                    assert end == "cone" and point is not None and \
                        np.count_nonzero(np.asarray(point) != V[v]) == 1, (side, v, d, end)   # along a cube edge
    # the three sides at the corner (0, 0, 0) in one chart around its UV (0, 0) (bottom, front and left in the quadrants
    # 1, 2, 3), cut between left and bottom: from each of their 6 triangles at the corner every direction is the
    # chart's ray, along the cube edge the chart puts there (a ray on an edge between two triangles clockwise of the
    # start was missed: +v from the left side traced the -u ray, -u from it and +v from the front were invalid_start)
    def chart(side, p):
        x, y, z = p
        return {0: (y, x), 1: (-z, x), 2: (-z, -y), 3: (x + 5, y), 4: (z + 8, x), 5: (y + 11, z)}[side]
    squares = [[(x, y, 0) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))], [(x, 0, z) for x, z in ((0, 0), (1, 0), (1, 1), (0, 1))],
               [(0, y, z) for y, z in ((0, 0), (1, 0), (1, 1), (0, 1))], [(x, y, 1) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))],
               [(x, 1, z) for x, z in ((0, 0), (1, 0), (1, 1), (0, 1))], [(1, y, z) for y, z in ((0, 0), (1, 0), (1, 1), (0, 1))]]
    F, UV, FUV, side_of = [], [], [], []
    for side, q in enumerate(squares):
        for tri in ((0, 1, 2), (0, 2, 3)):
            pts = [q[k] for k in tri]
            uv = [chart(side, p) for p in pts]
            if (uv[1][0] - uv[0][0]) * (uv[2][1] - uv[0][1]) < (uv[1][1] - uv[0][1]) * (uv[2][0] - uv[0][0]):
                pts, uv = pts[::-1], uv[::-1]                 # counter-clockwise in UV
            F.append([x + 2 * y + 4 * z for x, y, z in pts])
            FUV.append([len(UV) + k for k in range(3)])
            UV.extend(uv)
            side_of.append(side)
    F, UV, FUV = np.array(F), np.array(UV, dtype=float), np.array(FUV)
    along = {"+u": (0, 1, 0), "+v": (1, 0, 0), "-u": (0, 0, 1), "-v": (0, 1, 0)}   # -v: the cut edge seen from the left
    starts = [(f, list(F[f]).index(0)) for f in range(len(F)) if side_of[f] < 3 and 0 in F[f]]
    assert len(starts) == 6
    for f, c in starts:
        for d, point in along.items():
            assert ray(f, c, d) == ("cone", point), (side_of[f], f, d, ray(f, c, d))


def quad_degrees(QF, n):
    """The number of quad edges at each of the n quad vertices."""
    edges = {(min(q[k], q[(k + 1) % 4]), max(q[k], q[(k + 1) % 4])) for q in QF for k in range(4)}
    degree = np.zeros(n, dtype=np.int64)
    for a, b in edges:
        degree[a] += 1
        degree[b] += 1
    return degree


def check_valences_against_quads(V, F, UV, FUV, QF, report, weld=False):
    """quad_valences() of the map: at every quad vertex that is a vertex of the map, the valence it has in the quad
    mesh extracted from it (the cross-check that makes a VVAL file trustworthy)."""
    valence, r = ss.quad_valences(V, F, UV, FUV, weld=weld)
    assert r["status"] == "SUCCESS" and valence.shape == (len(V),) and r["border"].shape == (len(V),)
    degree = quad_degrees(QF, len(report["QV_vertex"]))
    at_vertices = [i for i, row in enumerate(report["QV_vertex"]) if row >= 0]
    assert len(at_vertices) > 0
    assert all(valence[report["QV_vertex"][i]] == degree[i] for i in at_vertices)
    return valence, r


def test_quad_valences_and_vval(tmp_path):
    V, F, UV, FUV = unit_cube()
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV)
    for S in (1.0, 2.0):                                   # grid scale 2: a face's center is a regular quad vertex
        QV, QF, r = ss.extract_quad_mesh(V, F, UV, FUV, grid_scale=S)
        check_quad_mesh(V, F, UV, FUV, QV, QF, r, grid_scale=S)
        valence, vr = check_valences_against_quads(V, F, UV, FUV, QF, r)
        assert len(QF) == 6 * S * S and list(valence) == [3] * 8 and not vr["border"].any()
    # rows no face uses: valence 0; a map with a border: the directions of each border vertex's fan
    valence, _ = ss.quad_valences(np.vstack([V, [[5.0, 5.0, 5.0]]]), F, UV, FUV)
    assert list(valence) == [3] * 8 + [0]
    Vc, Fc, UVc, FUVc = cut_grid(n=8, noise=1e-9, size=8.0, t=(3.0, 1.0))
    UV2, FUV2, _ = ss.snap(Vc, Fc, UVc, FUVc, integer_grid_map=True)
    QV, QF, r = ss.extract_quad_mesh(Vc, Fc, UV2, FUV2)
    valence, vr = check_valences_against_quads(Vc, Fc, UV2, FUV2, QF, r)
    corners = [0, 8, 72, 80]                              # the grid's corners: 2; other border vertices 3, inside 4
    assert sorted(np.flatnonzero(vr["border"])) == [i for i in range(81) if i % 9 in (0, 8) or i // 9 in (0, 8)]
    assert all(valence[i] == (2 if i in corners else 3 if vr["border"][i] else 4) for i in range(81))
    # the VVAL file: header, count, one line per vertex; refusals write nothing
    path = tmp_path / "cube.vval"
    assert "8 vertex valences" in ss.write_vval(path, [3] * 8)
    assert path.read_text() == '{"file_format":"VVAL","version":1}\n8\n' + "3\n" * 8
    for bad, match in [([3, -1], "valence -1"), ([2 ** 31], "valence 2147483648"), ([[3, 3]], "1-D"), ([3.5], "integers"),
                       (4, "1-D")]:                       # a scalar: was written as a file of one vertex
        with pytest.raises(ss.InputError, match=match):
            ss.write_vval(tmp_path / "bad.vval", bad)
    assert not (tmp_path / "bad.vval").exists()
    # refusals: a map that is not exactly seamless, a folded one (its faces listed, as rows of F)
    Vt, Ft, UVt, FUVt = flat_torus(n=4, noise=1e-10)
    with pytest.raises(ss.SnapError) as e:
        ss.quad_valences(Vt, Ft, UVt, FUVt)
    assert e.value.report["status"] == "INVALID_INPUT" and "not exactly seamless" in e.value.report["message"]
    Vt, Ft, UVt, FUVt = flat_torus(n=4)
    UVt = UVt.copy()
    UVt[FUVt[Ft == 5]] = [3.0, 1.0]                        # vertex (1, 1) moved to (3, 1): fold-overs
    valence, r = ss.quad_valences(Vt, Ft, UVt, FUVt, raise_on_failure=False)
    assert valence is None and r["status"] == "FOLD_OVERS" and len(r["fold_overs"]) > 0
    assert sorted(r["fold_overs"]) == [f for f in range(len(Ft)) if orientations(Ft, UVt, FUVt)[f] < 0]
    assert ss.quad_valences(V, F[:, :2], UV, FUV, raise_on_failure=False)[1]["status"] == "INVALID_INPUT"


def test_quantize():
    # the unit cube's map scaled by 1.3: its translations and cones are integers at no grid scale; quantize=True gives
    # it integer translations (each cone onto one of the four integer points around it),
    # and the integer-grid snap makes it exact and fold-free: a quad mesh with the 8 cones as its irregular vertices
    V, F, UV, FUV = unit_cube()
    with pytest.raises(ss.SnapError) as e:
        ss.snap(V, F, UV * 1.3, FUV, integer_grid_map=True, grid_scale=2.0)
    assert e.value.report["status"] == "INVALID_INPUT" and "not quantized" in e.value.report["message"]
    assert not e.value.report["quantized"]
    UV2, FUV2, r = ss.snap(V, F, UV * 1.3, FUV, integer_grid_map=True, grid_scale=2.0, quantize=True)
    assert r["quantized"] and ss.is_exact_integer_grid_map(V, F, UV2, FUV2, grid_scale=2.0)
    assert r["flips_after_repair"] == 0 and r["degenerate_after_repair"] == 0 and r["total_max_change_cells"] < 2
    QV, QF, q = ss.extract_quad_mesh(V, F, UV2, FUV2, grid_scale=2.0)
    check_quad_mesh(V, F, UV2, FUV2, QV, QF, q, grid_scale=2.0)
    valence, _ = check_valences_against_quads(V, F, UV2, FUV2, QF, q)
    assert list(valence) == [3] * 8 and q["irregular_vertices"] == 8
    # a map near an integer-grid map is rounded as without it, bit for bit
    UV3, _, r3 = ss.snap(V, F, UV, FUV, integer_grid_map=True, quantize=True)
    UV4, _, _ = ss.snap(V, F, UV, FUV, integer_grid_map=True)
    assert not r3["quantized"] and UV3.tobytes() == UV4.tobytes()


def flat_grid_scaled(n, scale=1.7):
    """A flat grid of n x n vertices, its UVs (i, j) times `scale`, one UV row per vertex: (V, F, UV)."""
    V = np.array([[i, j, 0.0] for j in range(n) for i in range(n)])
    F = np.array([f for j in range(n - 1) for i in range(n - 1) for a in [j * n + i]
                  for f in ([a, a + 1, a + n + 1], [a, a + n + 1, a + n])])
    return V, F, scale * V[:, :2]


def test_quantize_aligned_side_between_isolines():
    # a flat 6 x 6 grid of squares, UV = 1.7 (i, j): its right side lies at u = 8.5, half-way between two isolines, and
    # its corner vertex 1e-9 beyond. The border edges of a side share their ends' variables, so they lie on one isoline;
    # rounded edge by edge (each at its first end), the side went to u = 8 and u = 9 at once: INFEASIBLE
    n = 6
    V, F, UV = flat_grid_scaled(n)
    UV[n - 1, 0] += 1e-9
    UV2, FUV2, r = ss.snap(V, F, UV, F, integer_grid_map=True, quantize=True)
    assert r["quantized"] and ss.is_exact_integer_grid_map(V, F, UV2, FUV2)
    right = UV2[FUV2[np.isin(F, np.arange(n - 1, n * n, n))]][:, 0]     # the corners of the right side's vertices
    assert len(set(right.tolist())) == 1 and right[0] in (8.0, 9.0)


def test_cut_mesh_welded_by_default():
    # a cut mesh (the faces above the cut with their own copies of the vertices, bit-identical positions, as libigl and
    # Directional write maps): read without welding its seam was a border, and snap() said SUCCESS, "already exactly
    # seamless" with 0 cut edges; now welded by default (weld=None), as the command line does
    n = 8
    V, F, UV, FUV = cut_grid(n=n, noise=1e-9)
    Vc, Fc = np.vstack([V, V]), F.copy()
    Fc[len(F) // 2:] += len(V)                            # the faces of rows j >= n / 2
    assert ss.is_cut_mesh(Vc, Fc) and not ss.is_cut_mesh(V, F)
    UV2, FUV2, r = ss.snap(Vc, Fc, UV, FUV)
    _, _, r1 = ss.snap(V, F, UV, FUV)                       # the mesh itself: not a cut mesh, nothing welded
    assert r["welded_automatically"] and not r1["welded_automatically"] and r["cut_edges"] == r1["cut_edges"] > n
    assert ss.is_exactly_seamless(Vc, Fc, UV2, FUV2) and not ss.is_exactly_seamless(Vc, Fc, UV, FUV)
    _, _, r0 = ss.snap(Vc, Fc, UV, FUV, weld=False)         # asked not to weld: the seam is a border
    assert not r0["welded_automatically"] and r0["cut_edges"] < r1["cut_edges"]
    assert r0["cut_edges"] + n == r1["cut_edges"]             # (every edge between two faces' own UV rows is a cut edge)
    # a trace from a corner of the copy: its start is the row F has there (it was the first row of the vertex, 16 less)
    f = len(Fc) - 1
    t = ss.trace_isoline(Vc, Fc, UV2, FUV2, f, 0, "+u")
    assert t["status"] == "SUCCESS" and t["start"] == Fc[f, 0] >= len(V)


# Zero-area faces (1, 0, 2) whose long side 0-2 is a border edge, their middle vertex 1 at (1, 0) lifted in 3D: the quad
# mesh has vertex 1 on its border. quad_valences() counted the middle corner as 180 degrees inside (valence 4) and the
# extraction's own check refused the maps with EXACTNESS_CHECK_FAILED ("internal error").
# - the square [0, 2] x [0, 1] as 4 triangles, vertex 1 interior in the mesh: a point of a straight border, degree 3;
# - an ear (its short side 1-2 on the border too), vertex 1 a border vertex of the mesh at a corner of the quad: degree 2
#   (3 with the first version of the rule for an interior middle vertex)
@pytest.mark.parametrize("F,top,quads,degree", [([[0, 1, 4], [1, 3, 4], [1, 2, 3], [1, 0, 2]], [2, 1, 0], 2, 3),
                                                ([[0, 1, 4], [1, 3, 4], [1, 0, 2]], [1, 1, 0], 1, 2)])
def test_collapsed_face_on_border(F, top, quads, degree):
    F = np.array(F)
    V = np.array([[0, 0, 0], [1, 0, -0.3], [2, 0, 0], top, [0, 1, 0]], float)
    QV, QF, r = ss.extract_quad_mesh(V, F, V[:, :2], F)
    check_quad_mesh(V, F, V[:, :2], F, QV, QF, r, closed=False)
    valence, _ = check_valences_against_quads(V, F, V[:, :2], F, QF, r)
    assert len(QF) == quads and valence[1] == degree


def test_max_grid_cells_near_2_64():
    # faces whose UV boxes hold 2^62 cells each: with max_grid_cells = 2^64 - 1 their count wrapped around to 0 and
    # passed, and the allocation threw (MemoryError / ValueError); now RANGE_EXCEEDED, nothing returned
    a = 2.0 ** 30 - 0.5
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    UV = np.array([[-a, -a], [a, -a], [a, a], [-a, a]])
    F1 = np.array([[0, 1, 2], [0, 2, 3]])
    for copies in (2, 1):                                  # 2^64 cells (the sum), 2^63 (beyond any memory)
        F = np.vstack([F1 + 4 * i for i in range(copies)])
        QV, QF, r = ss.extract_quad_mesh(np.vstack([V + 5 * i for i in range(copies)]), F, np.vstack([UV] * copies), F,
                                         max_grid_cells=2 ** 64 - 1, raise_on_failure=False)
        assert r["status"] == "RANGE_EXCEEDED" and QV is None and QF is None


def test_integer_grid_options_need_integer_grid_map():
    # quantize, merge_cone_pairs and separate_cone_pairs act on integer translations: without integer_grid_map they
    # changed nothing and the report said nothing (SUCCESS, quantized False); refused like the command line's flags
    n = 4
    V, F, UV = flat_grid_scaled(n)
    before = UV.copy()
    for name in ("quantize", "merge_cone_pairs", "separate_cone_pairs"):
        with pytest.raises(ValueError, match=name + "=True needs integer_grid_map=True"):
            ss.snap(V, F, UV, F, **{name: True})
        assert np.array_equal(UV, before)
        assert ss.snap(V, F, UV, F, **{"integer_grid_map": True, "quantize": True, name: True})[2]["quantized"]


def test_integer_grid_map_within_one_cell():
    # a flat disk within one grid cell (UVs in [0.1, 0.35]) with a seam of translation (1e-13, -2e-13), 0 up to noise:
    # rounded to 0 it collapses nothing, so the snap succeeds (the refusal of maps within one cell whose rounded
    # translations collapse them must not take it); the same disk's seam with translation 0.2 is refused
    n = 4
    V = np.array([[i, j, 0.0] for j in range(n) for i in range(n)])
    UV = np.array([[0.1 + 0.25 * i / (n - 1), 0.1 + 0.25 * j / (n - 1)] for j in range(n) for i in range(n)])
    F = np.array([f for j in range(n - 1) for i in range(n - 1)
                  for f in ([j * n + i, j * n + i + 1, (j + 1) * n + i + 1], [j * n + i, (j + 1) * n + i + 1, (j + 1) * n + i])])
    for shift, status in [((1e-13, -2e-13), "SUCCESS"), ((0.2, 0.0), "INVALID_INPUT")]:
        UV2, FUV = list(map(list, UV)), F.copy()
        copies = {}
        for f in range(len(F)):                  # the faces right of column 1 see its vertices shifted: a seam
            if all(v % n >= 1 for v in F[f]):
                for k, v in enumerate(F[f]):
                    if v % n == 1:
                        copies.setdefault(v, len(UV2))
                        if copies[v] == len(UV2):
                            UV2.append([UV[v][0] + shift[0], UV[v][1] + shift[1]])
                        FUV[f][k] = copies[v]
        out = ss.snap(V, F, np.array(UV2), FUV, weld=False, integer_grid_map=True, align_boundary=False, raise_on_failure=False)
        assert out[2]["status"] == status, out[2]["message"]
        if status == "INVALID_INPUT":
            assert "spans less than one grid cell" in out[2]["message"] and "would collapse" in out[2]["message"]
        else:
            assert out[2]["cut_edges"] == 3 and out[2]["integer_translations_after"] == 3


def test_grid_scale_must_be_a_power_of_two():
    # is_exact_integer_grid_map() answered False for 3, 0, -1, NaN or inf (snap() and the others reported "not a power
    # of two"), and '2' was read as 2: every function taking grid_scale refuses them alike
    V, F, UV, FUV = flat_torus(n=4)
    calls = [lambda s: ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=s),
             lambda s: ss.snap(V, F, UV, FUV, integer_grid_map=True, grid_scale=s),
             lambda s: ss.diagnose_seamlessness(V, F, UV, FUV, integer_grid_map=True, grid_scale=s),
             lambda s: ss.extract_quad_mesh(V, F, UV, FUV, grid_scale=s)]
    for call in calls:
        for bad in [3, 0, -1, -2.0, float("nan"), float("inf"), "2", None, True, 1j, 2 ** 1100, Fraction(1, 3)]:
            with pytest.raises(ss.InputError, match="grid_scale must be"):
                call(bad)
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=np.float32(0.5))
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=Fraction(1, 2))   # as the package's exact outputs
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=Decimal(2))
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=np.array(2.0))
    assert ss.is_exact_integer_grid_map(V, F, UV, FUV, grid_scale=2) and ss.is_exact_integer_grid_map(V, F, UV, FUV)


def test_integer_grid_align_edges_beyond_2_52():
    # a 2 x 2 grid of squares at UV (2^52, 2^52) + [0, 2]^2: its border edges are align edges on isolines of 2^52 grid
    # units or more, beyond the integers an integer-grid map holds exactly: RANGE_EXCEEDED, naming an align edge and the
    # advice; at grid_scale 1/2 (isolines of 2^51 + {0, 1} grid units) it is an exact integer-grid map already
    n = 2
    V = np.array([[i, j, 0.0] for j in range(n + 1) for i in range(n + 1)])
    F = np.array([f for j in range(n) for i in range(n) for f in
                  ([j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1],
                   [j * (n + 1) + i, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i])])
    UV = V[:, :2] + 2.0 ** 52
    kept = UV.copy()
    out = ss.snap(V, F, UV, F, integer_grid_map=True, raise_on_failure=False)
    assert out[2]["status"] == "RANGE_EXCEEDED" and np.array_equal(UV, kept)
    assert out[2]["message"].startswith("align edge (") and "2^52 or more" in out[2]["message"]
    assert "scale the map down (grid_scale / --grid-scale)" in out[2]["message"]
    out = ss.snap(V, F, UV, F, integer_grid_map=True, grid_scale=0.5)
    assert out[2]["status"] == "SUCCESS" and out[2]["align_edges"] == 8 and np.array_equal(out[0], kept)


@pytest.mark.parametrize("name,weld", [("directional/horsers-param-full-seamless.obj", True),
                                       ("directional/spherer-param.obj", True)])
def test_extract_quad_mesh_shared_data(name, weld):
    V, F, UV, FUV = shared_map(name)
    UV2, FUV2, report = ss.snap(V, F, UV, FUV, weld=weld, integer_grid_map=True)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV2, FUV2, weld=weld)
    # welded: the rows of V with one position are one vertex; compare positions, not rows
    check_quad_mesh(V, F, UV2, FUV2, QV, QF, r)
    valence, _ = check_valences_against_quads(V, F, UV2, FUV2, QF, r, weld=weld)
    assert sum(v != 4 for v in {tuple(V[i]): valence[i] for i in range(len(V))}.values()) == r["cones"]
    lay = ss.quad_layout(QF)
    check_quad_layout(QF, lay)
    assert r["euler_characteristic"] == 2 and r["cones"] == report["field_cones"]
    # the map's motorcycle graph, traced exactly on its triangles, is the quad mesh's: the same patches, nodes, arcs
    traced = ss.motorcycle_graph(V, F, UV2, FUV2, weld=weld)["layout"]
    assert traced["valid"] and traced["patches"] == len(lay["LF"])
    assert (traced["nodes"], traced["arcs"]) == (lay["vertices"] - lay["loop_splits"], lay["arcs"] - lay["loop_splits"])


def test_extract_quad_mesh_of_a_cut_mesh_not_welded():
    # Directional's torus map is a cut mesh: with weld=False its seams are borders and the extraction is refused
    # ("cells that form several fans ... use a larger grid_scale", which helped at no scale); the message now names the
    # weld, which extracts it
    V, F, UV, FUV = shared_map("directional/torus-hex-param.obj")
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV, integer_grid_map=True)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV2, FUV2, weld=False, raise_on_failure=False)
    assert QV is None and r["status"] == "INVALID_INPUT" and "is a cut mesh (is_cut_mesh())" in r["message"]
    QV, QF, r = ss.extract_quad_mesh(V, F, UV2, FUV2)
    assert r["status"] == "SUCCESS" and r["euler_characteristic"] == 0


def test_quad_mesh_in_one_call_shared_data():
    # fandisk: as snap(integer_grid_map=True, merge_cone_pairs=True) then extract_quad_mesh(), bit for bit; Directional's
    # full-seamless dragon, whose cone pairs on one integer point are moved apart and one of whose branched cells takes
    # in the cell of a 90-degree cone: a closed quad mesh, chi 2
    V, F, UV, FUV = shared_map("libqex/fandisk_param.obj")
    QV, QF, r = ss.quad_mesh(V, F, UV, FUV)
    UV2, FUV2, _ = ss.snap(V, F, UV, FUV, integer_grid_map=True, merge_cone_pairs=True, separate_cone_pairs=True)
    QV2, QF2, _ = ss.extract_quad_mesh(V, F, UV2, FUV2)
    assert np.array_equal(QF, QF2) and np.array_equal(QV, QV2) and np.array_equal(r["UV"], UV2)
    V, F, UV, FUV = shared_map("directional/dragon-param-full-seamless.obj")
    QV, QF, r = ss.quad_mesh(V, F, UV, FUV, threads=2)
    sides = [tuple(sorted((a, b))) for q in QF for a, b in zip(q, np.roll(q, -1))]
    uses = {}
    for e in sides:
        uses[e] = uses.get(e, 0) + 1
    assert all(n == 2 for n in uses.values()) and all(len(set(q)) == 4 for q in QF)     # closed, four corners each
    assert len(QV) - len(uses) + len(QF) == 2 == r["euler_characteristic"] and r["covers_map"]
    assert ss.is_exact_integer_grid_map(V, F, r["UV"], r["FUV"])
    assert len(r["snap"]["separated_cone_pairs"]) > 0 and len(r["absorbed_cones"]) > 0
    # without the separation its 8 zero-area triangles are forced: refused, and the advice is not to untangle again
    QV, QF, r = ss.quad_mesh(V, F, UV, FUV, separate_cone_pairs=False, threads=2, raise_on_failure=False)
    assert QV is None and r["status"] == "FOLD_OVERS" and any(f["forced"] for f in r["snap"]["folds"])
    assert "untangle the map first" not in r["message"] + r["advice"] and "untangled the map already" in r["advice"]
    with pytest.raises(ss.InputError):                      # refused before the snap
        ss.quad_mesh(V, F, UV, FUV, max_grid_cells=-1)


def test_separate_cone_pairs():
    # libQEx's duck_qc_8 map: two cone pairs that its rounded translations put onto one integer point are joined by a
    # cut near that point; separate_cone_pairs=True moves them apart (the field kept) and no negative triangle is left
    V, F, UV, FUV = shared_map("libqex/duck_qc_8_param.obj")
    UV2, FUV2, r = ss.snap(V, F, UV, FUV, integer_grid_map=True, separate_cone_pairs=True)
    assert len(r["separated_cone_pairs"]) > 0 and r["separated_cut_edges"] >= len(r["separated_cone_pairs"])
    assert r["flips_after_repair"] == 0 and r["merged_cone_pairs"] == []
    assert all(pair not in r["collapsed_cone_pairs"] for pair in r["separated_cone_pairs"])
    assert ss.is_exact_integer_grid_map(V, F, UV2, FUV2)


def test_extract_quad_mesh_merged_cone_pairs():
    # libQEx's fandisk map puts a 90 and a -90 degree cone onto one integer point: without merging, its untangled
    # IGM winds wrongly there and is refused; merge_cone_pairs=True makes the pair regular and the quads follow
    V, F, UV, FUV = shared_map("libqex/fandisk_param.obj")
    UV1, FUV1, kept = ss.snap(V, F, UV, FUV, integer_grid_map=True)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV1, FUV1, raise_on_failure=False)
    assert QV is None and r["status"] == "INVALID_INPUT" and "onto one integer point" in r["message"]
    assert kept["merged_cone_pairs"] == []
    pairs = kept["collapsed_cone_pairs"]   # named next to the windings, as the pairs the merge makes regular
    assert len(pairs) >= 1 and 1 <= kept["cancelling_collapsed_cone_pairs"] <= len(pairs)
    assert all(a < b and any("the cones at vertices %d and %d" % (a, b) in w["message"] for w in kept["winding_defects"])
               for a, b in pairs)
    forced_corners = {v for f in kept["folds"] if f["forced"] for v in f["vertices"]}   # proven: not injective there
    assert all(w["forced"] == (w["vertex"] in forced_corners) for w in kept["winding_defects"])
    UV2, FUV2, merged = ss.snap(V, F, UV, FUV, integer_grid_map=True, merge_cone_pairs=True)
    assert len(merged["merged_cone_pairs"]) > 0 and merged["winding_defects"] == [] and merged["collapsed_cone_pairs"] == []
    assert merged["field_cones"] + 2 * len(merged["merged_cone_pairs"]) == kept["field_cones"]
    assert ss.is_exact_integer_grid_map(V, F, UV2, FUV2)
    QV, QF, r = ss.extract_quad_mesh(V, F, UV2, FUV2)
    check_quad_mesh(V, F, UV2, FUV2, QV, QF, r)
    assert r["euler_characteristic"] == 2 and r["irregular_vertices"] == merged["field_cones"]
