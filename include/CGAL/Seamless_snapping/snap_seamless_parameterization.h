// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_SNAP_SEAMLESS_PARAMETERIZATION_H
#define CGAL_SEAMLESS_SNAPPING_SNAP_SEAMLESS_PARAMETERIZATION_H

#include <CGAL/Seamless_snapping/Connection_constraint.h>
#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_inputs.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_pipeline.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * snaps an approximately seamless per-corner UV map of a triangle mesh to nearby UVs, still IEEE
 * doubles, that are *exactly* seamless: across every cut edge the UVs of the two faces are related
 * by a rotation by a multiple of 90 degrees plus a translation, and every align edge is exactly
 * parallel to the u or v axis, in real arithmetic (Mandad & Campen 2019, Sec. 5).
 *
 * The method (Sec. 5, 5.1, 5.3 of the paper):
 * 1. *Extraction.* A cut edge is an interior edge whose two faces disagree on the UV of one of
 *    its endpoints (or an edge of `seam_edge_map`). Around each vertex, the corners are grouped
 *    into sectors (fans between cut edges and the border); all corners of a sector share one UV,
 *    the sector variable. The rotation `k` of each cut edge is given (`rotation_map`) or fitted:
 *    one `k` per seam arc (chain of cut edges between cones, border vertices and vertices whose
 *    number of cut edges is not 2), maximizing the sum of `dot(R^k d_i, d_j)` over the arc's edges,
 *    which is robust to near-zero-length cut edges; on an exactly seamless input, each cut edge keeps
 *    the `k` for which its transition holds exactly. Cones are interior vertices whose UV angle
 *    sum, rounded to quarter turns, is not 2 pi.
 * 2. *Constraints.* Two rows of Eq. (4) per cut edge, `R^k (U_a^i - U_b^i) - (U_a^j - U_b^j) = 0`,
 *    and one row of Eq. (5) per align edge, `U_a|c - U_b|c = 0`.
 * 3. *Reduction* (default, Sec. 5.3): cumulative equations along the branches between nodes leave a
 *    small node system, which is projected exactly by `Exact_constraint_projection`; the other
 *    sectors of the branches follow by unit-coefficient rows evaluated with the safe dot product
 *    (Alg. 5), on the same fixed-point grid F_delta (Sec. 4.3).
 * 4. *Verification.* Every row of the full system is evaluated on the result in rational
 *    arithmetic (`CGAL::Gmpq`), with zero tolerance, before anything is written.
 *
 * Only the corners of sectors whose value changed are written, after the verification; a border
 * halfedge `h` is also updated when it holds the UV of the corner `prev(opposite(h))` (the
 * `Seam_mesh` convention). Sectors that are in no constraint keep their UVs bit for bit, and an
 * input that is already exactly seamless is left unchanged.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadWritePropertyMap` with
 *         `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a 2D point type
 *         (e.g. `CGAL::Exact_predicates_inexact_constructions_kernel::Point_2`) with `double`
 *         coordinates as value type; the kernel is found with `CGAL::Kernel_traits`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the triangle mesh (its connectivity is only read; the element numbering comes from CGAL's
 *        `get_initialized_vertex_index_map()` and its halfedge and face counterparts, which renumber the internal ids
 *        of a `Polyhedron_3` with ids that are not `0..n-1`, as every CGAL algorithm does; `vertex_index_map` and its
 *        counterparts are not read)
 * \param uv the corner UV map: for a non-border halfedge `h`, `get(uv, h)` is the UV of the corner
 *        (`target(h)`, `face(h)`), in UV units
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{seam_edge_map}
 *     \cgalParamDescription{a property map telling which interior edges are cut edges (seams)}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{the interior edges whose two faces disagree (as numbers) on the UV of an endpoint}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::seam_edge_map()`. Corners joined by an
 *                     edge that is not a seam must have the same UV, otherwise `INVALID_INPUT` is returned.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{rotation_map}
 *     \cgalParamDescription{the rotation of the transition across each cut edge: for `h = halfedge(e, tm)`,
 *                           the number `k` of quarter turns counter-clockwise that map the UV frame of `face(h)`
 *                           to the UV frame of `face(opposite(h))`, i.e. `R^k (U_a^i - U_b^i) = U_a^j - U_b^j` with
 *                           `R(x, y) = (-y, x)`, `i = face(h)`, `j = face(opposite(h))`, `a = source(h)`, `b = target(h)`.
 *                           Any integer is taken modulo 4. Only `halfedge(e, tm)` of each cut edge is read.}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *                    as key type and an integer type as value type}
 *     \cgalParamDefault{fitted from the UVs, one `k` per seam arc}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::rotation_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{rotation_tolerance}
 *     \cgalParamDescription{the largest deviation, in degrees, of the transition of a non-degenerate cut edge from
 *                           its rotation `k * 90` degrees; the same value, in radians, bounds the relative difference
 *                           of the edge's UV lengths on the two sides. A cut edge is degenerate when its UV length on
 *                           one side is below 1e-6 times the diagonal of the UV bounding box; it is not checked.}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1` (degree)}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::rotation_tolerance()`. A larger deviation
 *                     gives `NOT_QUARTER_TURN_SEAMLESS` (e.g. the 120 degree seams of CGAL's `Triangle` orbifold). A
 *                     value that is NaN, negative or infinite gives `INVALID_INPUT`.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{align_boundary}
 *     \cgalParamDescription{whether border edges whose UV direction is within `alignment_tolerance` of the u or v axis
 *                           get an alignment constraint (Eq. 5), which makes them exactly axis-parallel.
 *                           Degenerate border edges (UV length below 1e-6 times the UV diagonal) are never aligned.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::align_boundary()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{alignment_tolerance}
 *     \cgalParamDescription{the largest angle, in degrees, between the UV direction of an edge and the u or v axis for the
 *                           edge to count as aligned (border edges with `align_boundary`, and the edges of
 *                           `edge_is_constrained_map`)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1e-3` (degrees): aligned parametrizations are axis-parallel up to solver error, far below
 *                       this; free boundaries are rarely that close to an axis by chance}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::alignment_tolerance()`; NaN, negative or
 *                     infinite: `INVALID_INPUT`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{edges (features, border) that must be aligned with the u or v axis (Eq. 5); the aligned
 *                           component is inferred from the UV direction, in the face of `halfedge(e, tm)` (or the
 *                           non-border side). An edge that is not within `alignment_tolerance` of an axis gives
 *                           `INVALID_INPUT`.}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{no such edges}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{use_reduced_system}
 *     \cgalParamDescription{`true`: project the node system of Sec. 5.3 and propagate along the branches;
 *                           `false`: project the full sector system (slower by orders of magnitude on large meshes;
 *                           for comparisons)}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::use_reduced_system()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{repair_flips}
 *     \cgalParamDescription{whether UV triangles that snapping turned negatively oriented are repaired (Sec. 5.4):
 *                           one vertex of the triangle is moved into the kernel of its 1-ring, together with its
 *                           partner sector across a cut (by the rotated displacement, on the grid F_delta) or only
 *                           along its aligned axis, so that every constraint still holds exactly; node sectors stay
 *                           fixed. Each move is accepted only if exact orientation tests show that no triangle of
 *                           the 1-ring gets flipped or degenerate and the flip count drops. Every moved coordinate
 *                           stays within the largest change made by snapping of its input value, so `max_change`
 *                           does not grow. Flips already present in the input are tried as well.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::repair_flips()`. The report gives the
 *                     flips before, after snapping and after repair, and the introduced ones left unrepaired.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{minimal_change}
 *     \cgalParamDescription{`true`: before the exact projection, the UVs of all constrained sectors are moved to the
 *                           L2-closest point of the full constraint system (every row of Eq. 4, 5, 6-8, weighted by
 *                           `vertex_weight_map`), computed in floating point by a sparse LDL^T factorization of
 *                           `C W^-1 C^T` with iterative refinement; the node system is then snapped and the branches
 *                           propagated from that point (Sec. 5.3), so the change `||u - ubar||_2` is within grid
 *                           rounding (a few quanta `2^(K-52)`) of the smallest exact change. `false`: the paper's
 *                           Sec. 4.2 choice, where implied variables absorb the whole correction (several times
 *                           larger). The cut graph, sectors and rotations are always those of the input.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::minimal_change()`; the report gives the time in
 *                     `least_squares_ms`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_weight_map}
 *     \cgalParamDescription{a weight per vertex for the minimal change: it minimizes `sum_s w(v_s) |u_s - ubar_s|^2`
 *                           over the sectors `s` (one UV pair each) with `v_s` the vertex of the sector. A larger weight
 *                           makes the UVs of that vertex move less (relative to the others); scaling all weights by
 *                           one factor changes nothing. Only used with `minimal_change(true)`; checked in either
 *                           mode: a weight that is not positive and finite gives `INVALID_INPUT`.}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `double` as value type}
 *     \cgalParamDefault{all weights 1}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::vertex_weight_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{connection_constraints}
 *     \cgalParamDescription{connection constraints (Eq. 6): the two end vertices of each path lie on one isocurve of
 *                           the given UV coordinate, after transport along the path's face strip; a closed path is a
 *                           cycle constraint (Eq. 8): the isocurve through its vertex closes up. See
 *                           `Connection_constraint` for the face strip, the convention and the checks (an invalid path
 *                           gives `INVALID_INPUT`). One row per constraint joins the system; in the reduced system
 *                           (Sec. 5.3) the path endpoints become nodes and the translations of Eq. (7) at crossed cut
 *                           edges are rewritten in node variables with the cumulative equations (Eq. 9). The input
 *                           need not satisfy these constraints approximately, but the change then is as large as
 *                           their violation.}
 *     \cgalParamType{a range (e.g. `std::vector`) of
 *                    `CGAL::Seamless_snapping::Connection_constraint<boost::graph_traits<TriangleMesh>::%halfedge_descriptor>`}
 *     \cgalParamDefault{no connection or cycle constraints}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::connection_constraints()`; wrap a large range
 *                     in `std::cref()` to avoid a copy}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{integer_grid_map}
 *     \cgalParamDescription{snap to an exact integer-grid map (IGM, Bommes et al. 2009/2013), the input of quad
 *                           extractors such as libQEx: the translation `t` of every cut edge (`u -> R^k u + t`,
 *                           Eq. 3/7) is fixed to the integer vector nearest the input's, so that every cone of the
 *                           field (an interior vertex whose rotations `k` do not sum to a multiple of 4) sits on the
 *                           integer fixed point of its transitions, and every align edge lies on an integer isoline
 *                           (`u|c` = the integer nearest the input's). The rows have integer right-hand sides
 *                           (`C x = b`, the addendum's Eq. 2'); they join the system and the reduction like
 *                           connection constraints. Checks, each failing with nothing written: every translation
 *                           and isoline value must be within 1e-3 grid units of an integer (`INVALID_INPUT`, "not
 *                           near an integer-grid map", with advice: set `grid_scale`, or snap without this
 *                           parameter); around every interior vertex the rounded transitions must compose to the
 *                           identity when the rotations do (`INFEASIBLE`, naming the vertex); the fixed point of a
 *                           cone's rounded transitions must be an integer point within 1e-3 of the input
 *                           (`INFEASIBLE`, naming the cone and the half-integer point). Vertices whose UV angle
 *                           sum is not 2 pi only because of fold-overs (their rotations compose to the identity)
 *                           are not pinned and are listed in `Snap_report::not_field_cones`.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::integer_grid_map()`; check the result with
 *                     `is_exact_integer_grid_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{grid_scale}
 *     \cgalParamDescription{`S`: the integer grid of the map is at multiples of `1/S` in UV units (e.g. MIQ maps with a
 *                           gradient size of 1/8). The UVs are multiplied by `S` inside and divided by it on output;
 *                           both are exact because `S` must be a power of two (otherwise `INVALID_INPUT`).
 *                           `RANGE_EXCEEDED` if a UV or a result would overflow or underflow.}
 *     \cgalParamType{`double`, a power of two}
 *     \cgalParamDefault{1}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::grid_scale()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{pinned_corner_map}
 *     \cgalParamDescription{corners whose UV is kept bit-identical, in both modes: `true` for `h` pins the corner
 *                           whose UV `uv[h]` holds (for a border halfedge, the corner it mirrors). The two variables
 *                           of the corner's sector become constants, rows `x = p` with `p` the corner's input UV and
 *                           right-hand sides `b != 0` (the addendum's Eq. 2'); the sector's vertex becomes a node of
 *                           the reduction, and neither the minimal change nor the flip repair moves it. The corner
 *                           mesh is expressed in units of `2^E` with `E` at most the lowest set bit of every pinned
 *                           coordinate, so that the pinned values are integers there; the result stays scale
 *                           covariant. Refused, with the corner named by vertex and face and `uv` untouched:
 *                           a pinned UV with
 *                           set bits below the quantum `2^(K-52)` of the fixed-point grid, which no snapped value can
 *                           have (`RANGE_EXCEEDED`; the message gives the quantum to round to); pins that contradict
 *                           the constraints, e.g. across a cut branch or a cone pinned off its integer point in the
 *                           integer-grid mode (`INFEASIBLE`). `Snap_report::pinned_sectors` counts the pinned
 *                           sectors.}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{no corner is pinned}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::pinned_corner_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{untangle}
 *     \cgalParamDescription{whether the fold-overs of the map are removed inside the space of maps with the same
 *                           constraints (beyond the paper, whose Sec. 5.4 only repairs what the snap introduces): every
 *                           UV triangle that is not positively oriented after the exact snap, and every interior vertex
 *                           around which the triangles do not wind as its valence (local injectivity; the valence is the
 *                           input's angle sum where no input triangle there is non-positive, else 4 at a regular vertex,
 *                           5 or 3 at a cone of +-90 degrees, 2 or 6 at a 180-degree cone), is untangled by moving the UVs
 *                           of the vertices within k face rings (k = 1, 2, 4, 8, 16) along the null space of the constraint
 *                           rows (transitions with their rotations, alignment, connections, pins, and in integer-grid mode
 *                           the integer translations and cone positions): the untangling energy of Garanzha et al. 2021
 *                           ("Foldover-free maps in 50 lines of code") with the input's own UV triangles as reference
 *                           shapes, minimized by Newton's method with their eps continuation, then a minimal-change polish
 *                           (the change to the snapped map plus a 1e-3-weighted barrier, every iterate fold-free). The
 *                           untangled floating-point map is then snapped exactly like the input (Sec. 4, 5.3), repaired
 *                           (Sec. 5.4) and verified; only UVs near the fold-overs change. Triangles that no map with these
 *                           constraints makes positive (two corners forced onto one UV point, e.g. two cones rounded onto
 *                           one integer point; three fixed corners on one line) are proven so exactly and left alone.
 *                           `Snap_report::folds` lists every triangle that is not positive at the end, with its reason
 *                           (proven forced or not), and `Snap_report::winding_defects` every vertex left not locally
 *                           injective (in integer-grid mode typically next to a cone pair the rounding collapsed onto one
 *                           integer point, which the message names); the report's untangling fields give the counts
 *                           before, after untangling, after the snap and after repair, and the change (max and RMS, in UV
 *                           units; times `Snap_report::grid_scale` in grid cells) next to that of the snap alone.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{the value of `integer_grid_map`: on where an integer-grid map is asked for (quad meshing, layouts),
 *                       off for plain snapping, which then keeps the input's fold-overs (and still lists them)}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::untangle()`. It moves UVs by up to a fraction of a
 *                     grid cell, far more than the snap's rounding: see the manual, "Untangling".}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_untangle_change}
 *     \cgalParamDescription{the largest move of a UV coordinate, in grid cells (UV units times `grid_scale`), that the
 *                           untangling may make beyond the snap; an untangled map that moves further is not used (the
 *                           snap of the input is written, `Snap_report::untangle_refused` is set and the message says why)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{no bound}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::max_untangle_change()`; NaN or negative:
 *                     `INVALID_INPUT` (infinity: no bound)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{merge_cone_pairs}
 *     \cgalParamDescription{with `integer_grid_map`: a +90 and a -90 degree cone (valence 3 and 5) that the rounded
 *                           translations put onto one integer point, joined by a path of edges whose vertices all lie
 *                           within one grid cell of that point (S cells at a `grid_scale` S > 1, where the map is S times
 *                           as large in cells; cut edges where possible, else edges that become cut edges), become
 *                           regular points of the field: the rotation k of every edge of that path changes by the same
 *                           quarter turns and its integer translation so that the transition still maps the point onto
 *                           itself (beyond the paper; libQEx merges such pairs into one regular quad vertex). No locally injective map keeps both cones on one point, so without
 *                           it the untangled map winds wrongly there and `extract_quad_mesh()` refuses it. Pairs whose
 *                           indices do not cancel are then joined the same way: the first cone becomes a regular point, the
 *                           second takes both indices (two +90 degree cones: valence 2; two -90: valence 6), never below
 *                           valence 2 (`Snap_report::joined_cone_pairs`; a half-turn cone counts as valence 2 or 6,
 *                           whichever allows the join; two such joined points whose rotations cancel, four -90 degree
 *                           cones in all, become one valence-8 point). Three +90 degree cones on one point keep two
 *                           cones there (joined, they would make valence 1), which the untangling cannot open (forced
 *                           zero-area triangles; `separate_cone_pairs` moves one off the point). The pairs are
 *                           listed in `Snap_report::merged_cone_pairs`, not counted in `Snap_report::field_cones`; the
 *                           result is an exact integer-grid map of the changed field (the caller's rotations change on
 *                           `Snap_report::merged_cut_edges` cut edges, `Snap_report::added_cut_edges` of them new; a
 *                           feature edge of `edge_is_constrained_map` among them stays exactly aligned, but the face across
 *                           it is turned by the new rotation: iso-u in one face, iso-v in the other).}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false` (the caller's field is kept); the `seamless_quad` program turns it on
 *                       (`--keep-cone-pairs` turns it off). `true` without `integer_grid_map`: `INVALID_INPUT`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::merge_cone_pairs()`; implemented in
 *                     `internal/surface/cone_merging.h`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{separate_cone_pairs}
 *     \cgalParamDescription{with `integer_grid_map`: two cones (any indices) that the rounded translations put onto one
 *                           integer point, joined by a path of cut edges whose vertices all lie within two grid cells of
 *                           that point (2 S cells at a `grid_scale` S > 1, where the map is S times as large in cells),
 *                           are moved apart instead, after `merge_cone_pairs` if both are set: the side of that
 *                           path on its left moves by an integer vector relative to the other (the integer translation of
 *                           every cut edge of the path changes; every other vertex of it keeps the identity), chosen among
 *                           those that put each cone on a neighbouring integer point, on no other cone's point near it, nearest its
 *                           input position (beyond the paper: a local re-rounding; the field and its cones are kept). With
 *                           `untangle` (the default here), a pair that keeps fold-overs within three face rings tries its
 *                           other admissible vectors, one more snap each (`Snap_report::separation_trials`), and keeps the
 *                           one with the fewest defects near it (all pairs' choices then snapped together, used only if
 *                           that has fewer defects in all): where the input puts the cones exactly onto one point, every
 *                           vector is as near to it, and they differ in what the untangling can reach. The
 *                           pairs are listed in `Snap_report::separated_cone_pairs`; the untangling then moves the map to
 *                           the new transitions, by up to about a grid cell near the pair. Pairs that no such cut path
 *                           joins are kept (and reported in `Snap_report::collapsed_cone_pairs` where defects are left), and
 *                           so are pairs whose indices cancel (a 90 and a -90 degree cone move as one: `merge_cone_pairs`
 *                           is for those).}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`; `true` without `integer_grid_map`: `INVALID_INPUT`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::separate_cone_pairs()`; implemented in
 *                     `internal/surface/cone_separation.h`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{quantize}
 *     \cgalParamDescription{with `integer_grid_map`: a map that is not near an integer-grid map at `grid_scale` (its
 *                           translations were never made integers: a seamless map such as Directional's rot-seamless output
 *                           or a map before MIQ's integer rounding) gets integer translations chosen for it instead of
 *                           `INVALID_INPUT` (beyond the paper: a quantization). The cut graph is peeled from its leaves: a
 *                           vertex all of whose cut edges but one have integer translations determines that one, a vertex
 *                           that is not a cone so that the transitions around it compose to the identity, a cone so that
 *                           its fixed point is the one of the four integer points around it that brings that translation
 *                           nearest to the input's (error diffusion), or the next of them where a cone near it (sharing a
 *                           face, or reached by a path of edges within two grid cells of the point) already holds that
 *                           point (two cones on one point force zero-area triangles), unless `merge_cone_pairs` will merge
 *                           the two, or where the point would make a triangle of three cones non-positive (its shape is
 *                           then fixed); where the graph leaves a choice (its cycles around handles, paths between border vertices) a translation is rounded; in each part of
 *                           the graph that does not reach the border one cone (of +-90 degrees where there is one) is left
 *                           to the end and takes the point that the others' rounding gives it. Then the integer-grid snap
 *                           runs as for any other integer translations, with the untangling (default) and its exact checks:
 *                           a choice that contradicts itself around a vertex is refused (`INFEASIBLE`), fold-overs left
 *                           are reported. The cones move by less than a grid cell in each coordinate (up to 2 in a
 *                           coordinate that an aligned chain fixes, or where the four integer points around a cone all
 *                           collide and it takes one within 2 cells), the map by up to a
 *                           few cells where the rounding adds up, and a coarse grid puts cones onto one point: choose a
 *                           `grid_scale` whose cells are smaller than the distances between the cones (`retinal_miq` of
 *                           ../shared/data, an MIQ map before its integer rounding: a verified quad mesh at every grid
 *                           scale from 1 to 32, the map moved by at most 1.08 grid cells; Directional's rot-seamless
 *                           dragon, 870 cones: at grid scale 4 with `merge_cone_pairs` and from 16 on, at most 4.8 cells). Without effect on a map that is
 *                           near an integer-grid map (its translations are rounded); `Snap_report::quantized` says whether
 *                           it ran. With align edges (feature edges, aligned border) each cone takes a point on the isolines
 *                           of the aligned chains through it where a chain already has one, and the chains that the cuts
 *                           join take one isoline (`internal/surface/isoline_classes.h`); the last cone of each part of the
 *                           cut graph and the translations rounded on its cycles are not chosen against the chains, and
 *                           where they contradict one the snap is refused `INFEASIBLE` saying so.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`; `true` without `integer_grid_map`: `INVALID_INPUT`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::quantize()`; implemented in
 *                     `internal/surface/integer_grid_quantization.h`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the 3D positions of the vertices, for the reference shapes of the untangling (triangles flipped
 *                           or thin in the input and those around wrongly wound vertices take their 3D shape, scaled to the
 *                           local UV scale); not used otherwise}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and a 3D point type as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_threads}
 *     \cgalParamDescription{with 2 or more, steps that depend on each other's results in no way run on two threads (the
 *                           node system of Sec. 5.3 and the minimal-change start point of the full system; the cone test
 *                           and the sectors of Sec. 5.1; the proofs of the faces left not positive and the windings of the
 *                           vertices; the implied variables of the core's evaluation (Alg. 3) in two halves of the IRREF
 *                           rows; with `untangle`, two halves of the regions that share no face or variable; with
 *                           `separate_cone_pairs`, two of its trial snaps at once); `0` takes
 *                           the machine's cores. The results are the same bits
 *                           whatever the number (only the report's times change). The 302K-face map of `../shared/large`
 *                           on two cores: see the user manual, "Large maps".}
 *     \cgalParamType{unsigned integer}
 *     \cgalParamDefault{`1` (the calling thread only)}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::number_of_threads()`; implemented with
 *                     `std::thread` (`internal/threads.h`)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{whether the status and message are printed to `std::cout`}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return a `Snap_report`. Its status is
 *   - `SUCCESS`: the map now is exactly seamless (checked in rational arithmetic), or already was;
 *   - `INVALID_INPUT`: no face, a face that is not a triangle, a NaN or infinite UV, corners of one sector
 *     with different UVs, an align edge without direction, an invalid connection or cycle path (the message
 *     names the constraint and the halfedge);
 *   - `NOT_QUARTER_TURN_SEAMLESS`: a transition is not a rotation by a multiple of 90 degrees (the message names the
 *     edge by its vertex indices and gives the angle);
 *   - `RANGE_EXCEEDED`, `SAFE_DOT_FAILED`, `INFEASIBLE`: the exact projection or the propagation failed
 *     (Sec. 4.3, 7), the message says where; `RANGE_EXCEEDED` also when the map is too close to the limits of
 *     double for an exact result at its scale (the grid quantum below 2^-1074 or delta above 2^1024 in UV units),
 *     or a pinned UV has bits below the grid quantum; `INFEASIBLE` also for pins that contradict the constraints;
 *   - `EXACTNESS_CHECK_FAILED`: the final exact check found a violated row (an internal error, never hidden).
 *   On any status other than `SUCCESS`, `uv` is left bit-identical.
 *   Lengths in the report are relative to the diagonal of the UV bounding box of the input.
 *   A `SUCCESS` with cut edges of zero UV length (`Snap_report::collapsed_cut_edges`) says so in its message.
 *
 * Scale: the result is scale covariant. The UVs are first scaled by a power of 2 so that the largest
 * |coordinate| lies in [1/2, 1) (exact), every step works on these values, and the result is scaled back;
 * a map scaled by 2^j therefore snaps to the result scaled by 2^j, bit for bit, whenever both are doubles.
 *
 * With `untangle(true)` (the default in integer-grid mode) the result is also free of fold-overs wherever the
 * constraints allow it; what they do not allow is listed in `Snap_report::folds` and `Snap_report::winding_defects`,
 * and a `SUCCESS` never hides a non-positive triangle: the message counts them.
 *
 * \warning The result consists of doubles and satisfies the constraints exactly; with `minimal_change(true)` it is
 * within grid rounding of the L2-closest such point, not exactly that point. Small triangles near the seams may flip; they are repaired locally when possible
 * (`repair_flips`), and the report counts flips in the input, after snapping and after repair.
 *
 * \sa `is_exactly_seamless()`, `Exact_constraint_projection`
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Snap_report snap_seamless_parameterization(const TriangleMesh& tm, HalfedgeUVMap uv,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const internal::Snap_inputs<TriangleMesh, NamedParameters> in(tm, np);
  return internal::snap_pipeline(tm, uv,
                                 [&](typename GT::edge_descriptor e) { return in.seam_of(e); }, in.has_seams,
                                 [&](typename GT::halfedge_descriptor h) { return in.rotation_of(h); }, in.has_rotations,
                                 [&](typename GT::edge_descriptor e) { return in.constrained_of(e); }, in.has_constrained,
                                 [&](typename GT::vertex_descriptor v) { return in.weight_of(v); }, in.has_weights,
                                 [&](typename GT::vertex_descriptor v) { return in.point_of(v); }, in.options);
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_SNAP_SEAMLESS_PARAMETERIZATION_H
