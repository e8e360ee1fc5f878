// Compile-and-run test of the named parameters: every parameter of the package chains with every
// other one and with CGAL's, in one expression, in either order, and each value is found again by
// CGAL's get_parameter(); a chain of all of them works forwards and backwards, and the older
// spelling NAME(v, np) still appends. Cheap to compile (no algorithm is instantiated); that the
// algorithms accept such a chain is exercised by test_snap and test_constraints.
#include <CGAL/Seamless_snapping/internal/parameters.h>

#include <iostream>

namespace SS = CGAL::Seamless_snapping;
namespace SP = CGAL::Seamless_snapping::parameters;

static int failures = 0, checks = 0;
#define CHECK(cond, what) do { ++checks; if(!(cond)) { std::cerr << "FAILED: " << what << "\n"; ++failures; } } while(0)

// the value stored for `tag` in `np`, or -1 when absent
template <class NP, class Tag>
int value_of(const NP& np, Tag tag)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, tag), -1);
}

// One descriptor per parameter: its tag, a distinct value, how to start a pack with it and how to
// append it to a pack.
#define SS_PARAMETER(TAG, NAME, VALUE)                                                 \
  struct P_##NAME {                                                                    \
    static constexpr int value = VALUE;                                                \
    static const char* name() { return #NAME; }                                        \
    static auto tag() { return TAG(); }                                                \
    static auto start() { return SP::NAME(VALUE); }                                    \
    template <class NP> static auto add(const NP& np) { return np.NAME(VALUE); }       \
  };
// the package's own parameters (every one of CGAL_SEAMLESS_SNAPPING_NAMED_PARAMETERS)
SS_PARAMETER(SS::snap_np::seam_edge_map_t, seam_edge_map, 1)
SS_PARAMETER(SS::snap_np::rotation_map_t, rotation_map, 2)
SS_PARAMETER(SS::snap_np::align_boundary_t, align_boundary, 3)
SS_PARAMETER(SS::snap_np::use_reduced_system_t, use_reduced_system, 4)
SS_PARAMETER(SS::snap_np::alignment_tolerance_t, alignment_tolerance, 5)
SS_PARAMETER(SS::snap_np::rotation_tolerance_t, rotation_tolerance, 6)
SS_PARAMETER(SS::snap_np::weld_vertices_t, weld_vertices, 7)
SS_PARAMETER(SS::snap_np::connection_constraints_t, connection_constraints, 8)
SS_PARAMETER(SS::snap_np::repair_flips_t, repair_flips, 9)
SS_PARAMETER(SS::snap_np::integer_grid_map_t, integer_grid_map, 13)
SS_PARAMETER(SS::snap_np::grid_scale_t, grid_scale, 14)
SS_PARAMETER(SS::snap_np::vt_per_corner_t, vt_per_corner, 15)
SS_PARAMETER(SS::snap_np::pinned_corner_map_t, pinned_corner_map, 16)
// CGAL's, as the package's functions take them
SS_PARAMETER(CGAL::internal_np::verbose_t, verbose, 10)
SS_PARAMETER(CGAL::internal_np::edge_is_constrained_t, edge_is_constrained_map, 11)
SS_PARAMETER(CGAL::internal_np::geom_traits_t, geom_traits, 12)
#undef SS_PARAMETER

template <class A, class B>
void check_pair()
{
  const auto ab = B::add(A::start());
  CHECK(value_of(ab, A::tag()) == A::value && value_of(ab, B::tag()) == B::value,
        A::name() << "(.)." << B::name() << "(.)");
}

template <class A, class... Bs> void check_row() { (check_pair<A, Bs>(), ...); }

template <class NP> auto chain(const NP& np) { return np; }
template <class NP, class P, class... Ps> auto chain(const NP& np) { return chain<decltype(P::add(np)), Ps...>(P::add(np)); }

template <class NP, class... Ps>
void check_all(const NP& np, const char* what)
{
  auto one = [&](auto tag, int value, const char* name) { CHECK(value_of(np, tag) == value, what << ": " << name); };
  (one(Ps::tag(), Ps::value, Ps::name()), ...);
}

template <class... Ps>
void run()
{
  (check_row<Ps, Ps...>(), ...);                                        // every ordered pair (incl. repeats)
}

int main()
{
  run<P_seam_edge_map, P_rotation_map, P_align_boundary, P_use_reduced_system, P_alignment_tolerance,
      P_rotation_tolerance, P_weld_vertices, P_connection_constraints, P_repair_flips,
      P_integer_grid_map, P_grid_scale, P_vt_per_corner, P_pinned_corner_map,
      P_verbose, P_edge_is_constrained_map, P_geom_traits>();

  const auto forward = chain<decltype(P_seam_edge_map::start()), P_rotation_map, P_align_boundary, P_use_reduced_system,
                             P_alignment_tolerance, P_rotation_tolerance, P_weld_vertices, P_connection_constraints,
                             P_repair_flips, P_integer_grid_map, P_grid_scale, P_vt_per_corner, P_pinned_corner_map, P_verbose,
                             P_edge_is_constrained_map, P_geom_traits>(P_seam_edge_map::start());
  const auto backward = chain<decltype(P_geom_traits::start()), P_edge_is_constrained_map, P_verbose, P_pinned_corner_map, P_vt_per_corner,
                              P_grid_scale, P_integer_grid_map, P_repair_flips,
                              P_connection_constraints, P_weld_vertices, P_rotation_tolerance, P_alignment_tolerance,
                              P_use_reduced_system, P_align_boundary, P_rotation_map, P_seam_edge_map>(P_geom_traits::start());
  check_all<decltype(forward), P_seam_edge_map, P_rotation_map, P_align_boundary, P_use_reduced_system, P_alignment_tolerance,
            P_rotation_tolerance, P_weld_vertices, P_connection_constraints, P_repair_flips, P_integer_grid_map,
            P_grid_scale, P_vt_per_corner, P_pinned_corner_map, P_verbose, P_edge_is_constrained_map, P_geom_traits>(forward, "forward chain");
  check_all<decltype(backward), P_seam_edge_map, P_rotation_map, P_align_boundary, P_use_reduced_system, P_alignment_tolerance,
            P_rotation_tolerance, P_weld_vertices, P_connection_constraints, P_repair_flips, P_integer_grid_map,
            P_grid_scale, P_vt_per_corner, P_pinned_corner_map, P_verbose, P_edge_is_constrained_map, P_geom_traits>(backward, "backward chain");

  // the older spelling appends to any pack, CGAL's own included
  const auto old = SP::repair_flips(9, SP::connection_constraints(8, CGAL::parameters::verbose(10)));
  check_all<decltype(old), P_repair_flips, P_connection_constraints, P_verbose>(old, "NAME(v, np)");
  // a parameter absent from a pack is reported absent
  CHECK(value_of(SP::verbose(true), SS::snap_np::repair_flips) == -1, "absent parameter");

  std::cout << checks - failures << " passed, " << failures << " failed" << std::endl;
  return failures == 0 ? 0 : 1;
}
