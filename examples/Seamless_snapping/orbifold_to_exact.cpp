// From CGAL's Orbifold Tutte embedding (seamless up to solver error) to an exactly seamless UV map.
//   orbifold_to_exact MESH.off CONES.selection.txt [OUT.obj [INPUT_OUT.obj]]
// OUT.obj receives the exact map, INPUT_OUT.obj the approximately seamless map before snapping; e.g. bear.off + bear.selection.txt from CGAL's data (scripts/demo.sh extracts them).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                   K;
typedef CGAL::Surface_mesh<K::Point_3>                   Mesh;
typedef Mesh::Halfedge_index                             halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, K::Point_2> UV_map;
namespace SS = CGAL::Seamless_snapping;

static int fail(const std::string& why) { std::fprintf(stderr, "orbifold_to_exact: %s\n", why.c_str()); return EXIT_FAILURE; }

int main(int argc, char** argv)
{
  if(argc < 3) return fail("usage: orbifold_to_exact MESH.off CONES.selection.txt [OUT.obj [INPUT_OUT.obj]]");
  Mesh sm;
  if(!CGAL::IO::read_polygon_mesh(argv[1], sm)) return fail(std::string("cannot read mesh ") + argv[1]);
  std::vector<Mesh::Vertex_index> cones;
  std::string msg;
  if(SS::internal::read_cone_selection_file(argv[2], sm, cones, msg) != SS::SUCCESS) return fail(msg);

  // corner map: uv[h] = UV of target(h) as seen from face(h)
  UV_map uv = sm.add_property_map<halfedge_descriptor, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  if(SS::internal::make_orbifold_tutte_uv(sm, uv, cones, SS::internal::SMP::Square, msg) != SS::SUCCESS) return fail(msg);
  std::printf("%s\n", msg.c_str());
  if(argc > 4 && SS::IO::write_OBJ_with_corner_uvs(argv[4], sm, uv, msg) != SS::SUCCESS) return fail(msg);

  // seam violation before: per cut edge the fitted quarter turn k, then |R^k d - d'| in CGAL::Gmpq
  const auto fit = SS::internal::fit_seam_transitions(sm, uv);
  std::printf("before: %zu cut edges, max seam violation %.3g (exact, relative to the UV diagonal), exactly seamless: %s\n",
              fit.cut_halfedges.size(), SS::internal::exact_max_seam_violation(sm, uv, fit),
              SS::is_exactly_seamless(sm, uv) ? "yes" : "no");

  const SS::Snap_report r = SS::snap_seamless_parameterization(sm, uv);
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);
  std::printf("snap: %.1f ms, max change %.3g, mean change %.3g (relative)\n", r.total_ms, r.max_change, r.mean_change);

  const double after = SS::internal::exact_max_seam_violation(sm, uv, fit);
  const bool exact = SS::is_exactly_seamless(sm, uv);
  std::printf("after:  max seam violation %.3g, exactly seamless: %s\n", after, exact ? "yes" : "no");
  if(!exact || after != 0) return fail("the snapped map is not exactly seamless");

  if(argc > 3) {
    if(SS::IO::write_OBJ_with_corner_uvs(argv[3], sm, uv, msg) != SS::SUCCESS) return fail(msg);
    std::printf("%s\n", msg.c_str());
  }
  return EXIT_SUCCESS;
}
