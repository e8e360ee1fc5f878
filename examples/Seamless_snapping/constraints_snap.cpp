// Public API: feature alignment (edge_is_constrained_map), a connection constraint
// (Connection_constraint, Eq. 6) and flip repair (Sec. 5.4) in one snap, with the named parameters
// chained in one expression.
//   constraints_snap IN.obj [OUT.obj]      (an OBJ with per-corner UVs, e.g. orbifold_to_exact's output)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Seamless_snapping/Connection_constraint.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <cmath>
#include <iostream>
#include <vector>

namespace SS = CGAL::Seamless_snapping;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Halfedge_index halfedge_descriptor;

int main(int argc, char** argv)
{
  if(argc < 2) { std::cerr << "usage: constraints_snap IN.obj [OUT.obj]\n"; return 1; }
  Mesh mesh;
  auto uv = mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(argv[1], mesh, uv, msg) != SS::SUCCESS) { std::cerr << msg << "\n"; return 1; }

  // UV vector of halfedge h in its face, and its angle to the nearest axis (degrees)
  auto vec = [&](halfedge_descriptor h) { return get(uv, h) - get(uv, mesh.prev(h)); };
  auto off_axis = [&](halfedge_descriptor h) {
    const K::Vector_2 d = vec(h);
    return std::atan2((std::min)(std::fabs(d.x()), std::fabs(d.y())), (std::max)(std::fabs(d.x()), std::fabs(d.y()))) * 180 / CGAL_PI;
  };

  // a feature: the interior edge closest to an axis direction, aligned exactly by the snap
  auto feature = mesh.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
  halfedge_descriptor best = *mesh.halfedges().begin();
  for(halfedge_descriptor h : mesh.halfedges())
    if(!mesh.is_border(mesh.edge(h)) && off_axis(h) < off_axis(best)) best = h;
  put(feature, mesh.edge(best), true);

  // a connection constraint: from the source of that edge, three steps along its direction in UV; the
  // two ends must end up on one isoline of the other coordinate
  const int component = std::fabs(vec(best).x()) > std::fabs(vec(best).y()) ? 1 : 0;
  std::vector<halfedge_descriptor> path(1, best);
  for(int step = 0; step < 2; ++step) {
    halfedge_descriptor next = Mesh::null_halfedge();
    double best_cos = -2;
    const K::Vector_2 d = vec(path.back());
    for(halfedge_descriptor h : CGAL::halfedges_around_source(mesh.target(path.back()), mesh)) {
      if(mesh.is_border(h)) continue;
      const K::Vector_2 e = vec(h);
      const double c = (d * e) / std::sqrt((d * d) * (e * e));
      if(c > best_cos) { best_cos = c; next = h; }
    }
    path.push_back(next);
  }
  std::vector<SS::Connection_constraint<halfedge_descriptor> > connections(1, {path, component});

  const SS::Snap_report r = SS::snap_seamless_parameterization(mesh, uv,
      SS::parameters::edge_is_constrained_map(feature).alignment_tolerance(45.).connection_constraints(connections)
                     .repair_flips(true));
  std::cout << SS::status_name(r.status) << ": " << r.message << "\n"
            << "feature edge off the axis after: " << off_axis(best) << " degrees; "
            << "flips introduced and left after repair: " << r.flips_unrepaired << "\n";
  if(r.status != SS::SUCCESS) return 1;
  if(!SS::is_exactly_seamless(mesh, uv, SS::parameters::edge_is_constrained_map(feature)) || off_axis(best) != 0) return 1;
  return argc > 2 && SS::IO::write_OBJ_with_corner_uvs(argv[2], mesh, uv, msg) != SS::SUCCESS ? 1 : 0;
}
