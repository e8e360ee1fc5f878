// Public API: the integer-grid-map (IGM) workflow. A map that is near an IGM (integer translations across the
// cuts, cones on integer points, up to solver error) is snapped to an exact IGM, checked, and written for a quad
// extractor such as libQEx: an OBJ with one vt per face corner and the vertex valences (VVAL).
//   integer_grid_snap IN.obj [GRID_SCALE [OUT.obj [OUT.vval]]]    (GRID_SCALE: a power of two, default 1)
// On quad_figure's bear map (CTest; the Parallelogram Orbifold Tutte map, 4 cones of 180 degrees) grid scale 4 is accepted:
// it is near an IGM (integer translations 0 -> 225 of 225 cut edges, cones on integer points 0 -> 4 of 4); grid scale 1 is
// refused (INFEASIBLE: a cone's fixed point at a half-integer; the message names grid scale 2). The Square map's cones
// of 90 degrees snap too, but have valence 1, which no quad mesh has: quad_valences() refuses them (INVALID_INPUT).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/VVAL.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/quad_valences.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace SS = CGAL::Seamless_snapping;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

static int fail(const std::string& why) { std::fprintf(stderr, "integer_grid_snap: %s\n", why.c_str()); return EXIT_FAILURE; }

int main(int argc, char** argv)
{
  if(argc < 2) return fail("usage: integer_grid_snap IN.obj [GRID_SCALE [OUT.obj [OUT.vval]]]");
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  Mesh mesh;
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(argv[1], mesh, uv, msg) != SS::SUCCESS) return fail(msg);
  std::printf("%s\ninput:  exact integer-grid map (grid scale %g): %s\n", msg.c_str(), scale,
              SS::is_exact_integer_grid_map(mesh, uv, SS::parameters::grid_scale(scale)) ? "yes" : "no");

  const SS::Snap_report r =
      SS::snap_seamless_parameterization(mesh, uv, SS::parameters::integer_grid_map(true).grid_scale(scale));
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);
  std::printf("snap:   %zu cut edges, %zu field cones, max change %.3g (relative)\n", r.cut_edges, r.field_cones, r.max_change);
  std::printf("        integer translations %zu -> %zu, cones on integer points %zu -> %zu\n",
              r.integer_translations_before, r.integer_translations_after,
              r.cones_on_integer_points_before, r.cones_on_integer_points_after);
  const bool igm = SS::is_exact_integer_grid_map(mesh, uv, SS::parameters::grid_scale(scale));
  std::printf("output: exact integer-grid map: %s\n", igm ? "yes" : "no");
  if(!igm || r.integer_translations_after != r.cut_edges || r.cones_on_integer_points_after != r.field_cones)
    return fail("the snapped map is not an exact integer-grid map");

  // the valences a quad extractor needs: the integer-grid directions leaving each vertex (4 regular, 3 and 5 at
  // cones), counted exactly; refused (FOLD_OVERS) when the map has fold-overs or zero-area UV triangles, and
  // (INVALID_INPUT) at a vertex of valence 1
  const SS::Quad_valences q = SS::quad_valences(mesh, uv);
  if(q.status != SS::SUCCESS) return fail(std::string("quad_valences: ") + SS::status_name(q.status) + ": " + q.message);
  std::size_t irregular = 0;
  for(std::size_t v = 0; v < q.valence.size(); ++v) irregular += (q.valence[v] != 4 && !mesh.is_border(Mesh::Vertex_index(v)));
  std::printf("valences: %zu interior vertices not of valence 4\n", irregular);

  if(argc > 3) {
    if(SS::IO::write_OBJ_with_corner_uvs(argv[3], mesh, uv, msg, SS::parameters::vt_per_corner(true)) != SS::SUCCESS) return fail(msg);
    std::printf("%s\n", msg.c_str());
  }
  if(argc > 4) {
    if(SS::IO::write_VVAL(argv[4], q.valence, msg) != SS::SUCCESS) return fail(msg);
    std::printf("%s\n", msg.c_str());
  }
  return EXIT_SUCCESS;
}
