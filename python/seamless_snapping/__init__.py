"""Exact seamless snapping of UV parametrizations (Mandad & Campen 2019, "Exact Constraint
Satisfaction for Truly Seamless Parametrization"), Python bindings of the C++/CGAL package.

Matrices follow libigl's convention: V (#V x 3 float), F (#F x 3 int, counter-clockwise),
UV (#UV x 2 float), FUV (#F x 3 int, rows of UV per face corner).

    V, F, UV, FUV = seamless_snapping.read_obj("in.obj")    # weld=True: the rows of a cut mesh's seams merged
    UV2, FUV2, report = seamless_snapping.snap(V, F, UV, FUV)
    d = seamless_snapping.diagnose_seamlessness(V, F, UV, FUV)           # where the input is not seamless, exactly
    seamless_snapping.write_obj("out.obj", V, F, UV2, FUV2)
    x, report = seamless_snapping.project(C, b, xbar)      # C: scipy.sparse or 2-D integer array
    graph = seamless_snapping.motorcycle_graph(V, F, UV2, FUV2)   # exact isoline tracing (Sec. 6.2)
    QV, QF, report = seamless_snapping.extract_quad_mesh(V, F, UV3, FUV3)   # the quad mesh of an exact integer-grid map
    valence, report = seamless_snapping.quad_valences(V, F, UV3, FUV3)     # per vertex, e.g. for libQEx: write_vval()

The functions that read a mesh (V, F, UV, FUV) weld as the command line does by default (weld=None): a cut mesh
(is_cut_mesh(): the border edges in pairs at bit-identical 3D points, as libigl and Directional write their maps; its
seams would otherwise be borders), or a mesh refused as it is but valid welded (a cut mesh with a hole at a seam);
weld=True / False weld or not. The vertex numbers inside report messages (a cone, a cut edge "(a, b)", a vertex whose
angle sum is wrong) count the vertices of that mesh: the rows of V that F uses, in their order, rows at one position one
vertex where it was welded, so they are rows of V only where every row is used and distinct; the structured fields
(e.g. diagnose_seamlessness()'s "edge", a trace's "start", quad_valences()' array) are rows of V.

snap, project, extract_quad_mesh and quad_valences return new arrays only when they succeed (report["status"] == "SUCCESS");
otherwise they raise SnapError (or, with raise_on_failure=False, return None in place of the arrays).
The tracing functions do not raise for a map they cannot read or trace: their dict has a "status" other than
"SUCCESS". Arguments refused before anything is computed (a file that cannot be read or written, index arrays
that do not hold integers, an unknown direction, a face or corner out of range) raise InputError, a ValueError
whose message names what was wrong and the valid values.
"""
import json
import math
import operator
import os
from fractions import Fraction

import numpy as np

from . import _core

__all__ = ["read_obj", "write_obj", "snap", "project", "is_exactly_seamless", "is_exact_integer_grid_map",
           "diagnose_seamlessness", "is_cut_mesh",
           "motorcycle_graph", "trace_isoline", "extract_quad_mesh", "quad_mesh", "quad_mesh_patches", "patch_vertex_grids",
           "quad_layout", "quad_valences", "write_vval",
           "DIRECTIONS", "SnapError", "InputError",
           "__version__"]
__version__ = _core.version

#: An argument refused before anything is computed: an OBJ file that cannot be read (the message is the C++
#: reader's, "<file>:<line>: <reason>") or written, index arrays that do not hold integers, an unknown isoline
#: direction, a face or corner out of range. A subclass of ValueError.
InputError = _core.InputError
InputError.__module__ = __name__


class SnapError(RuntimeError):
    """A snap, projection or quad extraction that did not succeed; `report` holds the status and the message."""

    def __init__(self, report):
        super().__init__("%s: %s" % (report["status"], report["message"]))
        self.report = report


def _integer_array(a, what, meaning, ndim=None):
    """`a` as a C-contiguous int64 array, or InputError unless every entry is an integer: an integer array, or
    floats with integral values (as SciPy may store integer matrices); with `ndim`, also unless it has that many
    dimensions (a scalar valence became a one-vertex VVAL file, a 3-D F a TypeError of the bindings)."""
    arr = np.asarray(a)
    if ndim is not None and arr.ndim != ndim:
        raise InputError("%s must be a %d-D array (%s), not of shape %s" % (what, ndim, meaning, arr.shape))
    # unsigned entries of 2^63 or more would wrap around to negative; compared in uint64 (against the Python int 2^63 - 1,
    # NumPy 1.24 compares in float64, where 2^63 equals it)
    too_large = arr > np.uint64(np.iinfo(np.int64).max) if arr.dtype.kind == "u" else None
    if too_large is not None and too_large.any():
        where = tuple(int(i) for i in np.argwhere(too_large)[0])
        raise InputError("%s must hold integers below 2^63 (%s); %s[%s] = %d is not one" %
                         (what, meaning, what, ", ".join(map(str, where)), int(arr[where])))
    if arr.dtype.kind in "iu":
        return np.ascontiguousarray(arr, dtype=np.int64)
    if arr.dtype.kind == "f":
        with np.errstate(invalid="ignore"):
            bad = ~np.isfinite(arr) | (np.abs(arr) >= 2.0 ** 62) | (arr != np.round(arr))
        if not bad.any():
            return np.ascontiguousarray(arr, dtype=np.int64)
        where = tuple(int(i) for i in np.argwhere(bad)[0])
        value = arr[where].item()
        raise InputError("%s must hold integers (%s); %s[%s] = %r is %s" %
                         (what, meaning, what, ", ".join(map(str, where)), value,
                          "2^62 or more" if math.isfinite(value) and value == round(value) else "not one"))
    raise InputError("%s must hold integers (%s), not values of type %s" % (what, meaning, arr.dtype))


def _mesh_arrays(V, F, UV, FUV):
    return (np.ascontiguousarray(V, dtype=np.float64), _integer_array(F, "F", "row indices of V", 2),
            np.ascontiguousarray(UV, dtype=np.float64), _integer_array(FUV, "FUV", "row indices of UV", 2))


def is_cut_mesh(V, F):
    """True iff two or more border edges of (V, F) lie on other border edges at bit-identical 3D points: a cut mesh
    (libigl and Directional write their parametrizations so, the vertices duplicated along the seams), whose seams
    are borders unless its vertices are welded (the C++ IO::cut_mesh_test(); -0 and 0 differ, as in the weld).
    False for arrays that do not form a triangle mesh as they are."""
    return _cut_mesh_test(V, F)[0]


def _cut_mesh_test(V, F):
    """(is_cut_mesh(), whether the command line would weld it) of (V, F): the C++ IO::cut_mesh_test() and the
    decision of IO::read_welding_cut_meshes()"""
    cut, weld = _core.cut_mesh_test(np.ascontiguousarray(V, dtype=np.float64), _integer_array(F, "F", "row indices of V", 2))
    return bool(cut), bool(weld)


def _weld(mesh, weld):
    """The weld of the functions that read a mesh (V, F, ...): weld=None (their default) welds as the command line
    does (IO::read_welding_cut_meshes()): a cut mesh (is_cut_mesh()), or a mesh refused as it is but valid welded (a
    cut mesh with a hole at a seam); True / False weld or not."""
    return bool(weld) if weld is not None else _cut_mesh_test(mesh[0], mesh[1])[1]


def read_obj(path, *, weld=False, threads=1):
    """Reads an OBJ file with per-corner texture coordinates (`f v/vt ...`, triangles) with the package's reader.

    Returns (V, F, UV, FUV) in the file's own layout, libigl's convention: V (#v x 3 float64) and UV (#vt x 2 float64)
    in file order, read bit for bit; F and FUV (#f x 3 int32), 0-based rows of V and UV per face corner.
    `weld=True` merges `v` lines with bit-identical coordinates into one row of V (the first; F refers to it):
    the cut meshes of libigl/Directional, whose vertices are duplicated along the seams, become the closed surface.
    `threads=2` (or more; 0 = the machine's cores) parses a file of 4 MiB or more in two halves at once: the same
    matrices, bit for bit.
    Raises InputError with the reader's message ("<path>:<line>: <reason>") for a file it cannot read.
    """
    V, F, UV, FUV, _ = _core.read_obj(os.fspath(path), bool(weld), _thread_count(threads))
    return V, F, UV, FUV


def write_obj(path, V, F, UV, FUV):
    """Writes the matrices as an OBJ file with per-corner texture coordinates: one `v` per row of V, one `vt` per row
    of UV, one `f v/vt v/vt v/vt` per face, each number the shortest decimal that reads back to the same double
    (read_obj reads them bit for bit).
    Atomic: the text goes to a temporary file that is then renamed. Raises InputError (nothing written) for arrays
    of the wrong shape, an index out of range, a value that is not finite, no face (read_obj refuses such a file),
    or a place that cannot be written. Returns the writer's one-line summary."""
    Vc, Fc, UVc, FUVc = _mesh_arrays(V, F, UV, FUV)
    if Fc.size == 0:
        raise InputError("F has no face: the file would hold no mesh (read_obj refuses a file without faces); "
                         "nothing written")
    return _core.write_obj(os.fspath(path), Vc, Fc, UVc, FUVc)


def snap(V, F, UV, FUV, *, weld=None, repair_flips=True, align_boundary=True, use_reduced_system=True,
         rotation_tolerance=1.0, alignment_tolerance=1e-3, minimal_change=True, integer_grid_map=False,
         grid_scale=1.0, untangle=None, max_untangle_change=float("inf"), merge_cone_pairs=False,
         separate_cone_pairs=False, quantize=False, threads=1, raise_on_failure=True):
    """Snap the per-corner UV map (UV, FUV) of the triangle mesh (V, F) to an exactly seamless one.

    Returns (UV_out, FUV_out, report): FUV_out equals FUV and UV_out equals UV except for the moved rows
    (rows shared by corners that were snapped apart are split; see the C++ reference). `report` is the
    C++ Snap_report as a dict. `weld=True` merges bit-identical vertices first; the default (None) welds a cut mesh
    (is_cut_mesh(): its seams would otherwise be borders, and the map be called "already exactly seamless" with no cut
    edge) or a mesh refused as it is but valid welded, as the command line does, and report["welded_automatically"]
    says so; weld=False never welds.
    `minimal_change=False` snaps the input itself (the paper's point) instead of the L2-closest point of the
    constraints; `integer_grid_map=True` snaps to an exact integer-grid map (integer translations, cones on
    integer points, aligned edges on integer isolines) whose grid is at multiples of 1/`grid_scale` (a power of 2).
    `untangle=True` removes the map's fold-overs inside the space of maps with the same constraints (then snaps
    exactly); the default (None) is `integer_grid_map`. What cannot be untangled is listed with its reason in
    report["folds"] (per face, "forced": proven by the constraints) and report["winding_defects"] (vertices whose
    UV angle sum is not their valence; "forced": a corner of a forced face, so no solution is injective there);
    report["closed_uncut_faces"] counts the faces of closed parts without cut edges (e.g. UVs made by a projection
    on a closed mesh), whose maps into the plane always fold: not untangled; an untangled map that moves a UV by
    more than `max_untangle_change` grid cells is not used (report["untangle_refused"]); a mirrored map (more
    negative than positive UV triangles in a connected component, e.g. its v axis flipped) is not untangled there
    (report["uv_mirrored"]: mirror the UVs of that component). `merge_cone_pairs=True` (with `integer_grid_map`) makes each
    pair of a 90 and a -90 degree cone that the rounded translations put onto one integer point (and a path within
    one grid cell of it joins, S cells at grid_scale S > 1) regular points of the field (report["merged_cone_pairs"]),
    as libQEx merges them, and then joins other pairs on one point (one
    cone takes both indices, never below valence 2, the other becomes regular: report["joined_cone_pairs"]);
    without it such maps keep winding defects,
    and report["collapsed_cone_pairs"] lists the pairs found next to them ("cancelling_collapsed_cone_pairs" of
    them are such 90/-90 degree pairs). `separate_cone_pairs=True` (with `integer_grid_map`) moves two cones that
    the rounded translations put onto one integer point apart instead, where a cut within two grid cells of it
    (2 S at grid_scale S > 1) joins them: the integer translations along that cut change so that each cone lands on
    a neighbouring integer point (report["separated_cone_pairs"]); the field is kept. Where fold-overs are left near a pair, its other ways apart
    are tried, one more snap each (report["separation_trials"]), and the one with the fewest defects near it is kept.
    A 90 and a -90 degree cone move as one: merge those. `quantize=True` (with `integer_grid_map`) gives a map that is
    not near an integer-grid map at `grid_scale` (its translations were never made integers, e.g. Directional's
    rot-seamless output or a map before MIQ's integer rounding) integer translations chosen for it instead of
    refusing it: each cone onto an integer point next to it (of the four around it, the one that keeps the translations
    nearest the map's; with align edges, one on the isolines of the aligned chains through it, up to 2 grid cells
    away), the translations from those along the cut graph, rounded where it leaves a choice
    (report["quantized"]); the map moves by up to a few grid cells, so choose a grid_scale whose cells are smaller than
    the distances between the cones. `threads=2` (or more; 0 = the machine's cores) runs the steps
    that do not depend on each other on two threads (the C++ number_of_threads): the same results, bit for bit.
    `quantize`, `merge_cone_pairs` and `separate_cone_pairs` without `integer_grid_map` raise ValueError (as the
    command line refuses them: they act on integer translations only; the C++ function ignores them).
    """
    for name, value in (("quantize", quantize), ("merge_cone_pairs", merge_cone_pairs),
                        ("separate_cone_pairs", separate_cone_pairs)):
        if value and not integer_grid_map:
            raise ValueError("%s=True needs integer_grid_map=True (it acts on the integer translations of an "
                             "integer-grid map); without it nothing would change" % name)
    if untangle is None:
        untangle = integer_grid_map
    arrays = _mesh_arrays(V, F, UV, FUV)
    welded_automatically = weld is None and _weld(arrays, None)
    uv, fuv, text = _core.snap(*arrays, bool(weld) or welded_automatically,
                               repair_flips, align_boundary,
                               use_reduced_system, float(rotation_tolerance), float(alignment_tolerance),
                               bool(minimal_change), bool(integer_grid_map), _grid_scale(grid_scale), bool(untangle),
                               float(max_untangle_change), bool(merge_cone_pairs), bool(separate_cone_pairs),
                               bool(quantize), _thread_count(threads))
    report = json.loads(text)
    report["welded_automatically"] = welded_automatically
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return uv, fuv, report


def is_exactly_seamless(V, F, UV, FUV, *, weld=None):
    """True iff every seam transition of the corner map is a rotation by k*90 degrees plus a translation,
    exactly (rational arithmetic). Border edges are not checked for alignment here (diagnose_seamlessness() checks the
    rows snap() enforces, the aligned border included; the C++ function takes the edges to check)."""
    return bool(_core.is_exactly_seamless(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld)))


def is_exact_integer_grid_map(V, F, UV, FUV, *, weld=None, grid_scale=1.0):
    """True iff the corner map is exactly seamless, every cut edge has an integer translation and every cone
    sits on an integer point, all exactly (rational arithmetic), after multiplying the UVs by `grid_scale` (a power
    of 2). Border edges are not checked (diagnose_seamlessness(..., integer_grid_map=True) checks the aligned border
    on integer isolines; the C++ function takes the edges to check)."""
    return bool(_core.is_exact_integer_grid_map(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld), _grid_scale(grid_scale)))


def diagnose_seamlessness(V, F, UV, FUV, *, weld=None, align_boundary=True, rotation_tolerance=1.0,
                          alignment_tolerance=1e-3, integer_grid_map=False, grid_scale=1.0):
    """Checks the map, as it is, against exactly the constraint rows that snap() with the same keywords would enforce
    (rotations k fitted to it, transitions (Eq. 4), boundary alignment (Eq. 5), with integer_grid_map the integer
    translations, cone points and isolines), every row in rational arithmetic (C++ diagnose_seamlessness()), and
    says where it fails worst. Nothing is changed; it does not raise for a map it cannot read.

    Returns a dict: "status" ("SUCCESS" when the rows could be built; otherwise the snap's own refusal, e.g.
    "NOT_QUARTER_TURN_SEAMLESS" or, with integer_grid_map, "INVALID_INPUT" for a map not near an integer-grid map,
    with "message"), "exact" (every row holds exactly; None where the rows could not be built: not evaluated),
    "rows", "violated_rows", "violated_connections", and when a row is violated the worst one (the largest exact |C_i u - b_i|): "row", "kind" ("transition", "alignment",
    "transition or alignment", "connection"), "edge" (its two rows of V; None for a connection row), "corners"
    ([row of F, corner 0-2] per sector of the row), "residual" (a fractions.Fraction, exact, in UV units) and
    "residual_double". With weld=True the rows of V at one position are one vertex (cut meshes)."""
    d = _core.diagnose_seamlessness(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld), bool(align_boundary),
                                    float(rotation_tolerance), float(alignment_tolerance), bool(integer_grid_map),
                                    _grid_scale(grid_scale))
    if "residual" in d:
        d["residual"] = Fraction(d["residual"])
        d["corners"] = [tuple(c) for c in d["corners"]]
    return d


def project(C, b, xbar, *, delta_margin_bits=1, force_multiprecision=False, raise_on_failure=True):
    """Exact projection: doubles x near xbar with C x = b exactly (integer C and b; Sec. 4 of the paper).

    C: a scipy.sparse matrix (any format) or a 2-D array of integers; b: integers, one per row of C;
    xbar: floats, one per column. Returns (x, report): report as the C++ Projection_report, with "large_change" (the
    result is exact but moved x̄ by far more than x̄ violated the rows), "input_violation", "per_row_grids" and
    "minimal_change".
    """
    if hasattr(C, "tocoo"):
        coo = C.tocoo()
        shape, rows, cols, vals = coo.shape, coo.row, coo.col, coo.data
    else:
        dense = np.asarray(C)
        if dense.ndim != 2:
            raise InputError("C must be 2-D, it has %d dimensions" % dense.ndim)
        shape = dense.shape
        rows, cols = np.nonzero(dense)
        vals = dense[rows, cols]
    vals = _integer_array(vals, "C", "the coefficients of the constraint rows")
    b = _integer_array(np.ravel(b), "b", "the right-hand sides of the constraint rows")
    xbar = np.ascontiguousarray(np.ravel(xbar), dtype=np.float64)
    if b.size != shape[0]:
        raise InputError("b has %d entries, C has %d rows" % (b.size, shape[0]))
    if xbar.size != shape[1]:
        raise InputError("xbar has %d entries, C has %d columns" % (xbar.size, shape[1]))
    x, text = _core.project(int(shape[0]), int(shape[1]), np.asarray(rows, dtype=np.int64).tolist(),
                            np.asarray(cols, dtype=np.int64).tolist(), vals.tolist(), b.tolist(), xbar.tolist(),
                            _bounded_index(delta_margin_bits, "delta_margin_bits", -2 ** 31, 2 ** 31 - 1), bool(force_multiprecision))
    report = json.loads(text)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return x, report


#: the isoline directions of `trace_isoline`, in the UV chart of the start face
DIRECTIONS = {"+u": 0, "+v": 1, "-u": 2, "-v": 3}


def _direction(direction):
    """0..3 for a name of DIRECTIONS or an integer 0..3; InputError naming the valid values otherwise."""
    if isinstance(direction, str):
        if direction in DIRECTIONS:
            return DIRECTIONS[direction]
    elif not isinstance(direction, bool):
        try:
            d = operator.index(direction)
            if 0 <= d <= 3:
                return d
        except TypeError:
            pass
    raise InputError("unknown direction %r: the directions are %s (or 0, 1, 2, 3)" %
                     (direction, ", ".join(repr(k) for k in DIRECTIONS)))


def _index(x, what):
    """x as an int, or InputError unless it is an integer (a Python or NumPy integer, not a float)."""
    if not isinstance(x, bool):
        try:
            return operator.index(x)
        except TypeError:
            pass
    raise InputError("%s must be an integer, got %r" % (what, x))


def _bounded_index(x, what, low, high):
    """x as an int in [low, high], or InputError (instead of the bindings' TypeError for a value their C++ type lacks)."""
    n = _index(x, what)
    if not low <= n <= high:
        raise InputError("%s must be in [%d, %d], got %d" % (what, low, high, n))
    return n


def _tolerance(x, what):
    """x as a finite float >= 0, or InputError (a NaN would compare false everywhere)."""
    t = float(x)
    if not (math.isfinite(t) and t >= 0):
        raise InputError("%s must be a finite number >= 0, got %r" % (what, x))
    return t


def _grid_scale(x):
    """x as a float that is a power of 2, or InputError (the grid of an integer-grid map is at multiples of 1/x, applied
    exactly; is_exact_integer_grid_map() answered False for 3, 0 or NaN, and a string such as '2' was read as a number)"""
    if isinstance(x, (str, bytes, bool, np.bool_, complex, np.complexfloating)):
        raise InputError("grid_scale must be a number (a power of 2), not %r" % (x,))
    try:
        s = float(x)                                           # also a Fraction, a Decimal, a 0-d array
    except OverflowError:                                      # an int or Fraction beyond the doubles
        s = math.inf
    except (TypeError, ValueError):
        raise InputError("grid_scale must be a number (a power of 2), not %r" % (x,)) from None
    if not (math.isfinite(s) and s > 0 and math.frexp(s)[0] == 0.5 and s == x):
        raise InputError("grid_scale must be a power of 2 (UV units are multiplied by it exactly), got %r" % (x,))
    return s


def _thread_count(threads):
    """`threads` as a count in [0, 1024], or InputError."""
    n = _index(threads, "threads")
    if not 0 <= n <= 1024:
        raise InputError("threads must be in [0, 1024] (0: the machine's cores), got %d" % n)
    return n


def _exact_polyline(trace):
    trace["uv_exact"] = [tuple(tuple(Fraction(c) for c in point) for point in segment)
                         for segment in trace["uv_exact"]]
    return trace


def motorcycle_graph(V, F, UV, FUV, *, weld=None, max_faces=0, rotation_tolerance=1.0, exact_uv=True):
    """The motorcycle graph of the per-corner UV map (UV, FUV) of (V, F) (Sec. 6.2 of the paper): the
    separatrices from every cone of n quarter turns (its n axis rays) and from every border corner (the axis
    rays strictly inside its fan), traced exactly (rational arithmetic) and together in exact time (unit speed in
    UV), each stopping at a cone, the border or where it reaches the trail of a trace that passed there earlier;
    two that meet head-on both stop, of two that cross at the same time the one heading a quarter turn
    counter-clockwise from the other goes on (on an integer-grid map: the patches of `quad_mesh_patches` on the
    mesh of `extract_quad_mesh`). Without cones and border corners four traces (+u, +v, -u, -v) are seeded.

    Returns a dict: "status" ("SUCCESS", or why the map cannot be traced, e.g. "INVALID_INPUT" or
    "NOT_QUARTER_TURN_SEAMLESS"), "message", and on SUCCESS:
      "counts": separatrices, failed (ended in an inconsistency of the map), cones, border_corners,
                cones_with_wrong_ray_count, inexact_transfers (cut crossings that missed the edge point);
      "ends": number of separatrices per end kind (the C++ Trace_end names: "cone", "border",
              "earlier_trace", ..., and the failures "missed_at_cut", "oscillation_at_cut", ...);
      "seeded": True when the four traces were seeded (no cones, no border corners);
      "separatrices": one dict per trace (index = the "hit_trace" of the others), see `trace_isoline`, plus
              "source": "cone", "border_corner" or "seed";
      "layout": the patch layout of the separatrices (faces cut along them, exactly): "status" ("SUCCESS", or
              "INVALID_INPUT" when a UV triangle is flipped or degenerate), "message", "patches", "quad_patches"
              (disks with 4 right-angle corners whose UV image is an axis-aligned rectangle, checked exactly),
              "nodes", "arcs", "euler_characteristic" (nodes - arcs + patches), "surface_euler_characteristic",
              "valid" (every patch a quad and the Euler characteristics equal), and the wall times (ms) of its
              phases "subdivision_ms", "mesh_ms" (the refined mesh) and "measure_ms" (the patches);
      "trace_ms": the wall time (ms) of tracing the separatrices.
    A map that is not exactly seamless still gets a graph: its inexactness shows as failure ends.
    `max_faces` limits each trace (0: 20 times the number of faces, plus 100). `exact_uv=False` leaves out the
    separatrices' "uv_exact" (their "uv" stays): on the 302K-face map of ../shared/large, 535K Fractions that take
    about 1.6 s to make.
    """
    d = _core.motorcycle_graph(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld),
                               _bounded_index(max_faces, "max_faces", 0, 2 ** 62),
                               _tolerance(rotation_tolerance, "rotation_tolerance"),
                               bool(exact_uv))
    if exact_uv:
        for t in d.get("separatrices", []):
            _exact_polyline(t)
    return d


def trace_isoline(V, F, UV, FUV, face, corner, direction, *, weld=None, max_faces=0, rotation_tolerance=1.0):
    """Traces one isoline exactly from the vertex F[face, corner], along `direction` ("+u", "+v", "-u", "-v",
    or 0..3) in the UV chart of `face` (the sector of that corner), until a cone, the border, a closed loop,
    the face limit, or an inconsistency of the map. From a cone: the ray that the chart of `face` shows around the
    vertex, else the one reached turning counter-clockwise from the corner, else none ("invalid_start"); at a cone of 3
    quarter turns one of the four directions from a corner so gives another one's ray again, or none. A face that is
    not a row of F, a corner other than 0, 1, 2 or another direction raise InputError.

    Returns a dict: "status" and "message" (of reading the map), and on SUCCESS the trace:
      "end": how it ended (a C++ Trace_end name), "failure": True for an inconsistency of the map, "message";
      "start": the row of V it started from (welded, a vertex has a row per copy: the one F has at the trace's first
      corner, in "start_face", which may be another face of the vertex than `face`), "start_face": the row of F of its
      first chart (-1 if none);
      "faces_crossed", "length" (UV length, rounded), "inexact_transfers", "hit_trace";
      the polyline, one straight segment per face crossed (consecutive segments meet in one surface point):
      "faces": row of F of each segment, "directions": 0..3 (+u, +v, -u, -v in that face's chart),
      "uv": (#segments, 2, 2) source and target in the UV chart of the segment's face (the UVs of its corners),
            rounded to doubles; "uv_exact": the same points exactly, as fractions.Fraction;
      "points": (#segments + 1, 3) the polyline in 3D (exact barycentric coordinates, rounded to doubles).
    """
    d = _core.trace_isoline(*_mesh_arrays(V, F, UV, FUV), _bounded_index(face, "face", -2 ** 62, 2 ** 62),
                            _bounded_index(corner, "corner", -2 ** 31, 2 ** 31 - 1), _direction(direction),
                            _weld((V, F), weld),
                            _bounded_index(max_faces, "max_faces", 0, 2 ** 62), _tolerance(rotation_tolerance, "rotation_tolerance"))
    if d["status"] == "SUCCESS":
        _exact_polyline(d)
    return d


def _max_grid_cells(x):
    """extract_quad_mesh()'s max_grid_cells as a count (None: the C++ default_max_grid_cells), or InputError"""
    n = _core.default_max_grid_cells if x is None else _index(x, "max_grid_cells")
    if not 0 <= n < 2**64:
        raise InputError("max_grid_cells must be in [0, 2**64), got %d" % n)
    return n


def extract_quad_mesh(V, F, UV, FUV, *, weld=None, grid_scale=1.0, max_grid_cells=None, split_valence_one_cones=True,
                      fill_branched_cells=True, raise_on_failure=True):
    """The quad mesh of the exact, fold-free integer-grid map (UV, FUV) of (V, F) (e.g. the output of
    snap(..., integer_grid_map=True)): its vertices are the integer points of the map (UV times `grid_scale`, a
    power of 2), its edges the unit segments of the integer isolines, its faces the unit cells, all decided exactly.

    Returns (QV, QF, report): QV #QV x 3 float (3D positions, barycentric, rounded), QF #QF x 4 int (counter-clockwise
    in UV, consistently oriented), and the report: the C++ Quad_mesh_report as a dict ("status", "message", "quads",
    "quad_vertices", "irregular_vertices", "cones", "euler_characteristic", "boundary_loops", "valence_histogram",
    "incomplete_cells", "covers_map", "uv_area" (exact, "p/q"), "fold_overs", "zero_area_faces", times ...) plus the
    origins of the quad vertices and faces as arrays:
      "QV_location": 0 at a vertex of (V, F), 1 inside an edge, 2 inside a face;
      "QV_face": the row of F in whose UV chart "QV_uv" is given; "QV_uv": #QV x 2 int, the integer UV in grid units
              (the UV is QV_uv / grid_scale, exactly); "QV_vertex": the row of V at location 0, else -1;
      "QF_faces": per quad, the rows of F it covers;
      "QF_patch", "QF_patch_cell" (#QF x 2 int), "QF_patch_corner": the patches of the quad mesh (C++
              quad_mesh_patches(): its motorcycle graph, traces along the quad edges from every irregular vertex and
              border corner, each stopping at an earlier one, cut it into rectangles of quads): per quad its patch,
              its cell (i, j) in the patch's grid, and the rank k in its QF row of the vertex at the cell's corner
              (i, j) (QF[q, (k + 1) % 4] is at (i + 1, j), and so on counter-clockwise);
      "patches": a dict ("status", "patches", "rectangles", "all_rectangles", "nodes", "motorcycles", "sizes"
              ([width, height] per patch), ...).
    A cone of 90 degrees (valence 1, a singularity of index 3/4, e.g. in Directional's maps) has no cell: with
    split_valence_one_cones=True its 2 x 2 cells are made one quad, three of whose corners have valence 3 for it (the
    cone is no quad vertex; report["split_cones"]: the rows of V of such cones; the quads are 3 fewer than the UV area
    per split cone). A vertex around which the map winds m > 1 times inside a cell (a branch point, e.g. one the
    untangling left) covers that cell m times: with fill_branched_cells=True that 4m-gon is filled with 2m - 1 quads,
    4(m - 1) of whose corners have valence 5 (report["filled_branch_points"]: rows of V; m - 1 quads more than the UV
    area each); the cell of a cone of 90 degrees next to such a cell is filled with it (report["absorbed_cones"]: rows
    of V; one quad fewer than the UV area each).
    Refused (SnapError, or None in place of QV and QF with raise_on_failure=False): "INVALID_INPUT" (not an exact
    integer-grid map, a cone of valence 1 whose 2 x 2 cells are not four whole cells around two regular points, or any with
    split_valence_one_cones=False, a branch point on a grid line or next to another one, or any with
    fill_branched_cells=False, a grid too coarse for the surface, ...), "FOLD_OVERS" (fold-overs or
    zero-area UV triangles with two corners at one point, listed in report["fold_overs"] and
    report["zero_area_faces"]; report["advice"] says to untangle first where that can remove them), "RANGE_EXCEEDED". A zero-area UV triangle with three distinct (collinear) corners is
    collapsed onto its long side (listed in report["zero_area_faces"] on success too).
    Cells cut by a border that is not on an integer isoline are left out: report["incomplete_cells"].
    `max_grid_cells` bounds the unit cells of the integer grid in the faces' UV bounding boxes (in all; None: the C++
    default_max_grid_cells, 2**24): more are refused with "RANGE_EXCEEDED" (the work and the memory are linear in it,
    about 290 bytes per quad at the peak).
    """
    n = _max_grid_cells(max_grid_cells)
    QV, QF, text, origins = _core.extract_quad_mesh(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld), _grid_scale(grid_scale), n,
                                                    bool(split_valence_one_cones), bool(fill_branched_cells))
    report = json.loads(text)
    report.update(origins)
    if "patches" in report:
        report["patches"] = json.loads(report["patches"])
    if report["status"] == "INVALID_INPUT" and weld is not None and not weld and is_cut_mesh(V, F):
        # its seams are borders: the torus of ../shared cut open had cells forming several fans at them, and the
        # message's "use a larger grid_scale" did not help at any scale
        report["message"] += ("; (V, F) is a cut mesh (is_cut_mesh()) and weld=False leaves its seams as borders, "
                              "which may be the cause: weld=True (or the default weld=None) joins them")
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return QV, QF, report


def quad_mesh(V, F, UV, FUV, *, weld=None, grid_scale=1.0, quantize=False, untangle=True, merge_cone_pairs=True,
              separate_cone_pairs=True, split_valence_one_cones=True, fill_branched_cells=True, max_grid_cells=None,
              threads=1, raise_on_failure=True):
    """The quad mesh of an approximately integer-grid UV map in one call, as the seamless_quad command line makes it:
    snap(V, F, UV, FUV, integer_grid_map=True, ...) to an exact integer-grid map (untangled, the cone pairs on one
    integer point merged or moved apart, and with quantize=True integer translations chosen where the map has none),
    then extract_quad_mesh() of that map. The arguments mean what they mean there (threads: the snap's; the snap's
    other options at their defaults); the defaults are seamless_quad's (but threads=1: 0 takes the machine's cores, the
    same results).

    Returns (QV, QF, report): extract_quad_mesh()'s, with report["snap"] the snap's report and report["UV"],
    report["FUV"] the exact map (as snap() returns them); (UV, FUV) are not changed. Refused (SnapError, or None in
    place of QV and QF with raise_on_failure=False) where the snap or the extraction fails; where the snap failed,
    report holds "status", "message" ("snapping failed: ...") and "snap" only. With untangle=True a map refused for
    fold-overs or zero-area triangles was untangled already: report["advice"] says so instead of extract_quad_mesh()'s
    advice to untangle, and report["snap"]["folds"] and ["winding_defects"] say what is left and what is forced.
    """
    n = _max_grid_cells(max_grid_cells)                    # refused before the snap's work
    UV2, FUV2, snapped = snap(V, F, UV, FUV, weld=weld, integer_grid_map=True, grid_scale=grid_scale, untangle=untangle,
                              merge_cone_pairs=merge_cone_pairs, separate_cone_pairs=separate_cone_pairs,
                              quantize=quantize, threads=threads, raise_on_failure=False)
    if snapped["status"] != "SUCCESS":
        report = {"status": snapped["status"], "message": "snapping failed: " + snapped["message"], "snap": snapped}
        if raise_on_failure:
            raise SnapError(report)
        return None, None, report
    QV, QF, report = extract_quad_mesh(V, F, UV2, FUV2, weld=weld, grid_scale=grid_scale, max_grid_cells=n,
                                       split_valence_one_cones=split_valence_one_cones,
                                       fill_branched_cells=fill_branched_cells, raise_on_failure=False)
    advice = "; " + report.get("advice", "")
    if report["status"] == "FOLD_OVERS" and untangle and report.get("advice") and report["message"].endswith(advice):
        report["message"] = report["message"][:-len(advice)]
        report["advice"] = ("quad_mesh() untangled the map already: report[\"snap\"][\"folds\"] and "
                            "[\"winding_defects\"] say what is left and what the constraints force")
    report["snap"], report["UV"], report["FUV"] = snapped, UV2, FUV2
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return QV, QF, report


def quad_valences(V, F, UV, FUV, *, weld=None, raise_on_failure=True):
    """Per row of V, the number of integer-grid directions (the axis directions of the charts) that leave its vertex
    into the surface, decided exactly (C++ quad_valences()): the valence of the vertex in the quad mesh of an
    integer-grid map wherever it is an integer point (extract_quad_mesh()): at an interior vertex its UV angle sum in
    quarter turns (4 at a regular vertex, 3 and 5 at cones of -90 and +90 degrees), at a border vertex the axis
    directions of its fan (3 on a straight border along an isoline, 2 at a convex right-angle corner). A quad
    extractor that guesses it from floating-point angle sums can be told it instead: libQEx reads it from a VVAL
    file (write_vval()).

    Returns (valence, report): valence #V int64 (0 for a row no face uses, also where it lies at the position of a
    used one; with weld=True the used rows at one position are one vertex and get its valence), and the report as a
    dict: "status", "message", "border" (#V bool: the row's vertex is on the border of the quad mesh: a border
    vertex, or one that a zero-area triangle whose long side is a border edge folds onto the border), "fold_overs" and
    "zero_area_faces" (rows of F). Refused (SnapError, or None in place of valence with raise_on_failure=False): "INVALID_INPUT" (the map is not exactly seamless, so its angle sums need not
    be multiples of 90 degrees: snap() it first; or the arrays do not form a triangle mesh; or an interior vertex has
    valence 1, a cone of 90 degrees or a cone of 5 quarter turns that the map winds back to 1, which no quad mesh has:
    the message names it), "FOLD_OVERS" (a negatively
    oriented UV triangle, or a zero-area one with two corners at one point, listed: there the angle sum is a signed
    winding number that no quad mesh has; snap(..., untangle=True) removes fold-overs where the constraints allow). A
    zero-area triangle with three distinct collinear corners counts as the limit of a thin positive one, as
    extract_quad_mesh() collapses it (its middle corner 180 degrees, or, where its long side is a border edge, its
    middle vertex a border point).
    """
    report = _core.quad_valences(*_mesh_arrays(V, F, UV, FUV), _weld((V, F), weld))
    valence = report.pop("valence", None)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return valence, report


def write_vval(path, valence):
    """Writes one valence per vertex (e.g. the first result of quad_valences()) in libQEx's VVAL format, the optional
    third argument of its command-line tool, atomically (C++ IO::write_VVAL()): the line
    {"file_format":"VVAL","version":1}, the number of vertices, then one integer per line, in the order of the
    vertices of the mesh file that goes with it (write_obj(): the rows of V). Returns a line saying what was written;
    InputError (nothing written) for a valence below 0 or beyond a C int, an array that is not 1-D, or a file that
    cannot be written."""
    return _core.write_vval(os.fspath(path), _integer_array(valence, "valence", "one per vertex", 1))


def quad_mesh_patches(QF, *, raise_on_failure=True):
    """The patches of a quad mesh given by QF (#QF x 4 int, rows of vertex indices, counter-clockwise, e.g. the QF of
    extract_quad_mesh() or of another quad mesher): its motorcycle graph (traces along the quad edges from every
    vertex of valence other than 4 and border vertex with other than 2 quads, each stopping at an earlier one, C++
    quad_mesh_patches()) cuts it into rectangles of quads.

    Returns the report as a dict: "status", "message", "patches", "rectangles", "all_rectangles", "nodes",
    "motorcycles", "sizes" ([width, height] per patch, [0, 0] for one that is not a rectangle), and per row of QF
    "QF_patch" (its patch; -1 where nothing was computed), "QF_patch_cell" (#QF x 2: its cell (i, j) in the patch's
    grid) and "QF_patch_corner" (the rank k in its row of the vertex at the cell's corner (i, j); QF[q, (k + 1) % 4]
    is at (i + 1, j), and so on counter-clockwise). A row that cannot be added to a manifold quad mesh (a repeated
    vertex, an edge already in two quads or in one in the same direction) raises InputError; a vertex whose quads
    form several fans gives "INVALID_INPUT" (SnapError, or the report with raise_on_failure=False). The mesh's vertices
    are the indices QF uses (below 2^31, not necessarily contiguous: rows of QV that no quad uses are not part of it).
    """
    out = _core.quad_mesh_patches(_integer_array(QF, "QF", "rows of 4 vertex indices", 2))
    report = json.loads(out.pop("patches"))
    report.update(out)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return report


def quad_layout(QF, *, raise_on_failure=True):
    """The quad layout of a quad mesh given by QF (as in quad_mesh_patches()): the coarse polygon mesh with one face
    per patch of its motorcycle graph, whose vertices are the quad vertices at patch corners (irregular vertices,
    border corners, T-junctions where a trace ends on another) and whose edges, the arcs, are the chains of quad
    edges between them along the traces and the border (C++ quad_layout(); the "coarse mesh" of the patches).

    Returns the report as a dict: "status", "message", "vertices", "arcs", "faces", "border_arcs", "t_junctions",
    "self_adjacent_arcs" (arcs with one patch on both sides), "non_simple_faces" (polygons listing a vertex twice),
    "polygon_mesh" (neither occurs), "loop_splits" (vertices that split an arc from a vertex back to itself),
    "euler_characteristic" (that of the quad mesh), "patches" (the report of quad_mesh_patches(QF) without its
    per-row arrays), and the layout: "LV" (per layout vertex its vertex index in QF), "LF" (per patch, in the order
    of "patches"["sizes"], its polygon: indices into LV, counter-clockwise from the patch's grid corner (0, 0)),
    "LF_corner" (per polygon vertex: a corner of the patch's rectangle; the others are T-junctions on its sides),
    "LF_length" (per polygon side k: quad edges from vertex k to k + 1; between corners they add up to the patch's
    width, height, width, height). Where a patch meets a vertex twice its polygon lists it twice. Refusals as in
    quad_mesh_patches() (InputError for rows that are no quads of a manifold mesh; SnapError, or the report with
    raise_on_failure=False, for "INVALID_INPUT").
    """
    out = _core.quad_layout(_integer_array(QF, "QF", "rows of 4 vertex indices", 2))
    report = json.loads(out.pop("layout"))
    report["patches"] = json.loads(out.pop("patches"))
    report.update(out)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return report


def patch_vertex_grids(QF, report):
    """The vertices of each rectangle patch as a grid: for the report of quad_mesh_patches(QF) or of
    extract_quad_mesh() (the one that gave QF), a list with, per patch, an int array of shape (height + 1, width + 1)
    whose entry [j, i] is the vertex (row of QV) at the patch's grid point (i, j), e.g. the control points of a spline
    patch fitted to it; None for a patch that is not a rectangle. Where a patch meets itself across a trail (a band
    cut open once), the vertices of those two sides appear on both sides of its grid."""
    patches = report.get("patches") if isinstance(report, dict) else None
    patches = patches if isinstance(patches, dict) else report
    if not isinstance(report, dict) or "status" not in patches or "QF_patch" not in report:
        raise InputError("report must be the dict of quad_mesh_patches(QF) or extract_quad_mesh() (with its per-row "
                         "\"QF_patch\" arrays), not %s" % (type(report).__name__ if not isinstance(report, dict)
                                                          else "a dict without them"))
    if patches["status"] != "SUCCESS":
        raise SnapError(patches)
    QF = _integer_array(QF, "QF", "rows of QV", 2)
    if QF.shape[1] != 4 or len(QF) != len(report["QF_patch"]):           # (2-D: _integer_array())
        raise InputError("QF must be the %d x 4 quads that gave the report (it is %s): the report is of another "
                         "quad mesh" % (len(report["QF_patch"]), " x ".join(map(str, QF.shape))))
    grids = [None if w == 0 else np.full((h + 1, w + 1), -1, dtype=np.int64) for w, h in patches["sizes"]]
    offsets = ((0, 0), (1, 0), (1, 1), (0, 1))                 # the cell's corners, counter-clockwise from (i, j)
    for q, (p, (i, j), k) in enumerate(zip(report["QF_patch"], report["QF_patch_cell"], report["QF_patch_corner"])):
        if grids[p] is not None:
            for t, (di, dj) in enumerate(offsets):
                v, old = QF[q][(k + t) % 4], grids[p][j + dj, i + di]
                if old >= 0 and old != v:                      # one grid point, two vertices: QF's rows were reordered
                    raise InputError("QF row %d puts vertex %d at the grid point (%d, %d) of patch %d, where another row "
                                     "put vertex %d: the report is of another quad mesh" % (q, v, i + di, j + dj, p, old))
                grids[p][j + dj, i + di] = v
    return grids
