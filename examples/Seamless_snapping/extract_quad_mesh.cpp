// Public API: the quad mesh of a UV map. The map (e.g. an Orbifold Tutte or a field-aligned parametrization
// whose seam translations and cones are integers up to solver error) is snapped to an exact integer-grid map,
// then extract_quad_mesh() makes its quad mesh: every vertex an integer point of the map, every face a unit
// cell, checked and verified exactly; quad_mesh_patches() then cuts it into rectangles of quads (the motorcycle
// graph of the quad mesh), each quad a cell (i, j) of its patch's grid, and quad_layout() makes the coarse mesh of
// those patches (one polygon per patch, its sides chains of quad edges).
//   extract_quad_mesh IN.obj [GRID_SCALE [OUT.off]]     (GRID_SCALE: a power of two, default 1)
// CTest runs it on the bear map that quad_figure writes (Orbifold Tutte Parallelogram) at grid scale 4.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace SS = CGAL::Seamless_snapping;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

static int fail(const std::string& why) { std::fprintf(stderr, "extract_quad_mesh: %s\n", why.c_str()); return EXIT_FAILURE; }

int main(int argc, char** argv)
{
  if(argc < 2) return fail("usage: extract_quad_mesh IN.obj [GRID_SCALE [OUT.off]]");
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  Mesh mesh;
  // corner map: uv[h] = UV of target(h) as seen from face(h)
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(argv[1], mesh, uv, msg) != SS::SUCCESS) return fail(msg);

  // 1. an exact integer-grid map: integer translations across the cuts, cones on integer points
  const SS::Snap_report r =
      SS::snap_seamless_parameterization(mesh, uv, SS::parameters::integer_grid_map(true).grid_scale(scale));
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);

  // 2. its quad mesh, with where every quad vertex lies on the triangle mesh and which triangles each quad covers
  Mesh quads;
  auto origin = quads.add_property_map<Mesh::Vertex_index, SS::Quad_vertex_origin<Mesh> >("v:origin").first;
  auto covered = quads.add_property_map<Mesh::Face_index, std::vector<Mesh::Face_index> >("f:covered").first;
  const SS::Quad_mesh_report q = SS::extract_quad_mesh(mesh, uv, quads, SS::parameters::grid_scale(scale),
                                                       SS::parameters::vertex_origin_map(origin).face_origin_map(covered));
  if(q.status != SS::SUCCESS) return fail(std::string("quad mesh: ") + SS::status_name(q.status) + ": " + q.message);
  std::printf("%zu triangles -> %s\n", std::size_t(mesh.number_of_faces()), q.message.c_str());

  // a quad vertex at a mesh vertex, on an edge or inside a face, and its exact UV: (u, v) / grid scale
  std::size_t at[3] = {0, 0, 0};
  for(Mesh::Vertex_index v : quads.vertices()) ++at[origin[v].location];
  const SS::Quad_vertex_origin<Mesh>& o = origin[*quads.vertices().begin()];
  std::printf("quad vertices at mesh vertices %zu, on edges %zu, inside faces %zu; the first is (%lld, %lld) / %g in the "
              "chart of face %u; the first quad covers %zu triangles\n", at[0], at[1], at[2], (long long)o.u, (long long)o.v,
              scale, unsigned(o.face), covered[*quads.faces().begin()].size());
  if(!q.covers_map()) return fail("cells cut by the border were dropped");

  // 3. its patches: rectangles of width x height quads; per quad its patch, its cell (i, j), its bottom side
  auto patch = quads.add_property_map<Mesh::Face_index, SS::Quad_patch_location<Mesh> >("f:patch").first;
  const SS::Quad_patches p = SS::quad_mesh_patches(quads, patch);
  if(!p.all_rectangles()) return fail(std::string("patches: ") + SS::status_name(p.status) + ": " + p.message);
  const SS::Quad_patch_location<Mesh>& l = patch[*quads.faces().begin()];
  std::printf("patches: %s; the first quad is cell (%d, %d) of patch %zu (%d x %d quads), its corner (%d, %d) at quad "
              "vertex %u\n", p.message.c_str(), l.i, l.j, l.patch, p.patches[l.patch].width, p.patches[l.patch].height,
              l.i, l.j, unsigned(quads.source(l.bottom)));

  // 4. the quad layout: a face per patch; per layout halfedge its chain of quad edges (first halfedge, length)
  Mesh layout;
  auto arcs = layout.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
  const SS::Quad_layout lay = SS::quad_layout(quads, layout, arcs);
  if(lay.status != SS::SUCCESS) return fail(std::string("layout: ") + SS::status_name(lay.status) + ": " + lay.message);
  const Mesh::Halfedge_index h = layout.halfedge(*layout.faces().begin());
  std::printf("layout: %s; patch 0 starts with an arc of %d quad edges from quad vertex %u\n", lay.message.c_str(),
              arcs[h].length, unsigned(quads.source(arcs[h].first)));

  if(argc > 3) {
    if(!CGAL::IO::write_OFF(argv[3], quads, CGAL::parameters::stream_precision(17))) return fail("cannot write the quad mesh");
    std::printf("quad mesh written to %s\n", argv[3]);
  }
  return EXIT_SUCCESS;
}
