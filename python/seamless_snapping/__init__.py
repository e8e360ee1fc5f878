"""Exact seamless snapping of UV parametrizations (Mandad & Campen 2019, "Exact Constraint
Satisfaction for Truly Seamless Parametrization"), Python bindings of the C++/CGAL package.

Matrices follow libigl's convention: V (#V x 3 float), F (#F x 3 int, counter-clockwise),
UV (#UV x 2 float), FUV (#F x 3 int, rows of UV per face corner).

    UV2, FUV2, report = seamless_snapping.snap(V, F, UV, FUV)
    x, report = seamless_snapping.project(C, b, xbar)      # C: scipy.sparse or 2-D integer array

Both return new arrays only when every constraint holds exactly (report["status"] == "SUCCESS");
otherwise they raise SnapError (or, with raise_on_failure=False, return None in place of the arrays).
"""
import json

import numpy as np

from . import _core

__all__ = ["snap", "project", "is_exactly_seamless", "is_exact_integer_grid_map", "SnapError", "__version__"]
__version__ = _core.version


class SnapError(RuntimeError):
    """A snap or projection that did not succeed; `report` holds the status and the message."""

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
