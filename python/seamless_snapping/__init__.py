"""Exact seamless snapping of UV parametrizations (Mandad & Campen 2019, "Exact Constraint
Satisfaction for Truly Seamless Parametrization"), Python bindings of the C++/CGAL package.

Matrices follow libigl's convention: V (#V x 3 float), F (#F x 3 int, counter-clockwise),
UV (#UV x 2 float), FUV (#F x 3 int, rows of UV per face corner).

    UV2, FUV2, report = seamless_snapping.snap(V, F, UV, FUV)
    x, report = seamless_snapping.project(C, b, xbar)      # C: scipy.sparse or 2-D integer array
    graph = seamless_snapping.motorcycle_graph(V, F, UV2, FUV2)   # exact isoline tracing (Sec. 6.2)
    QV, QF, report = seamless_snapping.extract_quad_mesh(V, F, UV3, FUV3)   # the quad mesh of an exact integer-grid map

snap, project and extract_quad_mesh return new arrays only when they succeed (report["status"] == "SUCCESS");
otherwise they raise SnapError (or, with raise_on_failure=False, return None in place of the arrays).
The tracing functions do not raise for a map they cannot read or trace: their dict has a "status" other than
"SUCCESS" (only a face, corner or direction out of range raises ValueError or KeyError).
"""
import json
from fractions import Fraction

import numpy as np

from . import _core

__all__ = ["snap", "project", "is_exactly_seamless", "is_exact_integer_grid_map", "motorcycle_graph",
           "trace_isoline", "extract_quad_mesh", "DIRECTIONS", "SnapError", "__version__"]
__version__ = _core.version


class SnapError(RuntimeError):
    """A snap, projection or quad extraction that did not succeed; `report` holds the status and the message."""

    def __init__(self, report):
        super().__init__("%s: %s" % (report["status"], report["message"]))
        self.report = report


def _mesh_arrays(V, F, UV, FUV):
    return (np.ascontiguousarray(V, dtype=np.float64), np.ascontiguousarray(F, dtype=np.int64),
            np.ascontiguousarray(UV, dtype=np.float64), np.ascontiguousarray(FUV, dtype=np.int64))


def snap(V, F, UV, FUV, *, weld=False, repair_flips=True, align_boundary=True, use_reduced_system=True,
         rotation_tolerance=1.0, alignment_tolerance=1e-3, minimal_change=True, integer_grid_map=False,
         grid_scale=1.0, raise_on_failure=True):
    """Snap the per-corner UV map (UV, FUV) of the triangle mesh (V, F) to an exactly seamless one.

    Returns (UV_out, FUV_out, report): FUV_out equals FUV and UV_out equals UV except for the moved rows
    (rows shared by corners that were snapped apart are split; see the C++ reference). `report` is the
    C++ Snap_report as a dict. `weld=True` merges bit-identical vertices first (cut meshes).
    `minimal_change=False` snaps the input itself (the paper's point) instead of the L2-closest point of the
    constraints; `integer_grid_map=True` snaps to an exact integer-grid map (integer translations, cones on
    integer points, aligned edges on integer isolines) whose grid is at multiples of 1/`grid_scale` (a power of 2).
    """
    uv, fuv, text = _core.snap(*_mesh_arrays(V, F, UV, FUV), weld, repair_flips, align_boundary,
                               use_reduced_system, float(rotation_tolerance), float(alignment_tolerance),
                               bool(minimal_change), bool(integer_grid_map), float(grid_scale))
    report = json.loads(text)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return uv, fuv, report


def is_exactly_seamless(V, F, UV, FUV, *, weld=False):
    """True iff every seam transition of the corner map is a rotation by k*90 degrees plus a translation,
    exactly (rational arithmetic), and aligned boundaries are axis-parallel exactly."""
    return bool(_core.is_exactly_seamless(*_mesh_arrays(V, F, UV, FUV), weld))


def is_exact_integer_grid_map(V, F, UV, FUV, *, weld=False, grid_scale=1.0):
    """True iff the corner map is exactly seamless, every cut edge has an integer translation, every cone
    sits on an integer point and aligned edges lie on integer isolines, all exactly (rational arithmetic),
    after multiplying the UVs by `grid_scale` (a power of 2)."""
    return bool(_core.is_exact_integer_grid_map(*_mesh_arrays(V, F, UV, FUV), weld, float(grid_scale)))


def _integer_array(a, what):
    arr = np.asarray(a)
    if arr.dtype.kind in "iu":
        return arr.astype(np.int64)
    if arr.dtype.kind == "f" and np.all(np.isfinite(arr)) and np.all(arr == np.round(arr)) \
            and np.all(np.abs(arr) < 2.0 ** 62):
        return arr.astype(np.int64)
    raise ValueError("%s must hold integers" % what)


def project(C, b, xbar, *, delta_margin_bits=1, force_multiprecision=False, raise_on_failure=True):
    """Exact projection: doubles x near xbar with C x = b exactly (integer C and b; Sec. 4 of the paper).

    C: a scipy.sparse matrix (any format) or a 2-D array of integers; b: integers, one per row of C;
    xbar: floats, one per column. Returns (x, report).
    """
    if hasattr(C, "tocoo"):
        coo = C.tocoo()
        shape, rows, cols, vals = coo.shape, coo.row, coo.col, coo.data
    else:
        dense = np.asarray(C)
        if dense.ndim != 2:
            raise ValueError("C must be 2-D")
        shape = dense.shape
        rows, cols = np.nonzero(dense)
        vals = dense[rows, cols]
    vals = _integer_array(vals, "C")
    b = _integer_array(np.ravel(b), "b")
    xbar = np.ascontiguousarray(np.ravel(xbar), dtype=np.float64)
    if b.size != shape[0]:
        raise ValueError("b has %d entries, C has %d rows" % (b.size, shape[0]))
    if xbar.size != shape[1]:
        raise ValueError("xbar has %d entries, C has %d columns" % (xbar.size, shape[1]))
    x, text = _core.project(int(shape[0]), int(shape[1]), np.asarray(rows, dtype=np.int64).tolist(),
                            np.asarray(cols, dtype=np.int64).tolist(), vals.tolist(), b.tolist(), xbar.tolist(),
                            int(delta_margin_bits), bool(force_multiprecision))
    report = json.loads(text)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return x, report


#: the isoline directions of `trace_isoline`, in the UV chart of the start face
DIRECTIONS = {"+u": 0, "+v": 1, "-u": 2, "-v": 3}


def _exact_polyline(trace):
    trace["uv_exact"] = [tuple(tuple(Fraction(c) for c in point) for point in segment)
                         for segment in trace["uv_exact"]]
    return trace


def motorcycle_graph(V, F, UV, FUV, *, weld=False, max_faces=0, rotation_tolerance=1.0):
    """The motorcycle graph of the per-corner UV map (UV, FUV) of (V, F) (Sec. 6.2 of the paper): the
    separatrices from every cone of n quarter turns (its n axis rays) and from every border corner (the axis
    rays strictly inside its fan), traced exactly (rational arithmetic) and together, each stopping at a cone,
    the border or an earlier trace. Without cones and border corners four traces (+u, +v, -u, -v) are seeded.

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
              "valid" (every patch a quad and the Euler characteristics equal).
    A map that is not exactly seamless still gets a graph: its inexactness shows as failure ends.
    `max_faces` limits each trace (0: 20 times the number of faces, plus 100).
    """
    d = _core.motorcycle_graph(*_mesh_arrays(V, F, UV, FUV), bool(weld), int(max_faces), float(rotation_tolerance))
    for t in d.get("separatrices", []):
        _exact_polyline(t)
    return d


def trace_isoline(V, F, UV, FUV, face, corner, direction, *, weld=False, max_faces=0, rotation_tolerance=1.0):
    """Traces one isoline exactly from the vertex F[face, corner], along `direction` ("+u", "+v", "-u", "-v",
    or 0..3) in the UV chart of `face` (the sector of that corner), until a cone, the border, a closed loop,
    the face limit, or an inconsistency of the map.

    Returns a dict: "status" and "message" (of reading the map), and on SUCCESS the trace:
      "end": how it ended (a C++ Trace_end name), "failure": True for an inconsistency of the map, "message";
      "start": the row of V it started from, "start_face": the row of F of its first chart (-1 if none);
      "faces_crossed", "length" (UV length, rounded), "inexact_transfers", "hit_trace";
      the polyline, one straight segment per face crossed (consecutive segments meet in one surface point):
      "faces": row of F of each segment, "directions": 0..3 (+u, +v, -u, -v in that face's chart),
      "uv": (#segments, 2, 2) source and target in the UV chart of the segment's face (the UVs of its corners),
            rounded to doubles; "uv_exact": the same points exactly, as fractions.Fraction;
      "points": (#segments + 1, 3) the polyline in 3D (exact barycentric coordinates, rounded to doubles).
    """
    if isinstance(direction, str):
        direction = DIRECTIONS[direction]
    d = _core.trace_isoline(*_mesh_arrays(V, F, UV, FUV), int(face), int(corner), int(direction), bool(weld),
                            int(max_faces), float(rotation_tolerance))
    if d["status"] == "SUCCESS":
        _exact_polyline(d)
    return d


def extract_quad_mesh(V, F, UV, FUV, *, weld=False, grid_scale=1.0, raise_on_failure=True):
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
      "QF_faces": per quad, the rows of F it covers.
    Refused (SnapError, or None in place of QV and QF with raise_on_failure=False): "INVALID_INPUT" (not an exact
    integer-grid map, a cone of valence 1, a grid too coarse for the surface, ...), "FOLD_OVERS" (fold-overs or
    zero-area UV triangles, listed in report["fold_overs"] and report["zero_area_faces"]), "RANGE_EXCEEDED".
    Cells cut by a border that is not on an integer isoline are left out: report["incomplete_cells"].
    """
    QV, QF, text, origins = _core.extract_quad_mesh(*_mesh_arrays(V, F, UV, FUV), bool(weld), float(grid_scale))
    report = json.loads(text)
    report.update(origins)
    if report["status"] != "SUCCESS" and raise_on_failure:
        raise SnapError(report)
    return QV, QF, report
