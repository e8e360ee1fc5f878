// Public API end to end: CGAL's Orbifold Tutte embedding on a Seam_mesh (Surface_mesh_parameterization),
// its UV map converted to the package's corner map, snapped to an exactly seamless map, converted back,
// and written with CGAL's own UV output.
//   seam_mesh_snap [mesh.off [cones.selection.txt [out.off]]]     (defaults: CGAL's bear and its cones)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Seamless_snapping/Seam_mesh_uv.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <unordered_map>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace SS = CGAL::Seamless_snapping;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Property_map<SM::Edge_index, bool> Seam_edges;
typedef SM::Property_map<SM::Vertex_index, bool> Seam_vertices;
typedef CGAL::Seam_mesh<SM, Seam_edges, Seam_vertices> Seam_mesh;
typedef boost::graph_traits<Seam_mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  SM sm;
  const char* mesh_file = argc > 1 ? argv[1] : "data/meshes/bear.off";
  const char* cone_file = argc > 2 ? argv[2] : "examples/Surface_mesh_parameterization/data/bear.selection.txt";
  if(!CGAL::IO::read_polygon_mesh(mesh_file, sm)) { std::cerr << "cannot read " << mesh_file << "\n"; return 1; }

  // 1. CGAL's Orbifold Tutte embedding (Square orbifold: seams are quarter turns) on a Seam_mesh
  std::vector<SM::Vertex_index> cones;
  if(SMP::read_cones(sm, cone_file, std::back_inserter(cones)) != SMP::OK) { std::cerr << "cannot read cones\n"; return 1; }
  Seam_mesh mesh(sm, sm.add_property_map<SM::Edge_index, bool>("e:seam", false).first,
                 sm.add_property_map<SM::Vertex_index, bool>("v:seam", false).first);
  std::vector<SM::Edge_index> seam;
  SMP::compute_shortest_paths_between_cones(sm, cones.begin(), cones.end(), seam);
  for(SM::Edge_index e : seam) mesh.add_seam(source(e, sm), target(e, sm));
  std::unordered_map<vertex_descriptor, SMP::Cone_type> cone_types;
  SMP::locate_cones(mesh, cones.begin(), cones.end(), cone_types);
  std::unordered_map<vertex_descriptor, int> index;
  for(vertex_descriptor v : vertices(mesh)) index.emplace(v, int(index.size()));
  auto uv = sm.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;   // SMP's seam-mesh UV map
  halfedge_descriptor border;
  for(halfedge_descriptor h : halfedges(mesh)) if(is_border(h, mesh)) { border = h; break; }
  SMP::Orbifold_Tutte_parameterizer_3<Seam_mesh> orbifold(SMP::Square, SMP::Mean_value);
  if(orbifold.parameterize(mesh, border, cone_types, uv, boost::make_assoc_property_map(index)) != SMP::OK) {
    std::cerr << "the orbifold embedding failed\n"; return 1;
  }

  // 2. seam-mesh UVs -> corner UVs (in place), snap, back
  SS::seam_mesh_uv_to_corner_uv(mesh, uv, uv);
  std::cout << "exactly seamless before: " << std::boolalpha << SS::is_exactly_seamless(sm, uv) << "\n";
  const SS::Snap_report report = SS::snap_seamless_parameterization(sm, uv);
  std::cout << SS::status_name(report.status) << ": " << report.message << "\n";
  if(report.status != SS::SUCCESS || !SS::is_exactly_seamless(sm, uv)) return 1;
  SS::corner_uv_to_seam_mesh_uv(mesh, uv, uv);

  // 3. CGAL's UV output (an OFF of the seam mesh's UV layout), with 17 digits: the overload that takes
  //    the vertex and face lists writes to our stream (the one taking a border halfedge formats with 6)
  std::vector<vertex_descriptor> vs(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<boost::graph_traits<Seam_mesh>::face_descriptor> fs(faces(mesh).begin(), faces(mesh).end());
  std::ofstream out(argc > 3 ? argv[3] : "bear_exact_uv.off");
  out.precision(17);
  SMP::IO::output_uvmap_to_off(mesh, vs, fs, uv, boost::make_assoc_property_map(index), out);
  return out ? 0 : 1;
}
