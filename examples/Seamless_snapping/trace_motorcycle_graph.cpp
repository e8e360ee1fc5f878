// Public API: tracing the motorcycle graph (the separatrices from the cones) of a map before and after snapping.
// On an approximately seamless input, isolines that cross a cut land beside the exact continuation (inexact
// transfers) and may end in an inconsistency (Fig. 3); on the snapped map every crossing is exact and no trace fails.
// On orbifold_to_exact's bear map (CTest): input 14 inexact cut crossings and no failure, snapped 0 and 0.
//   trace_motorcycle_graph IN.obj [OUT.svg]    (an OBJ with per-corner UVs)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/trace_svg.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/Trace_end.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/trace_isoline.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace SS = CGAL::Seamless_snapping;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;

static int fail(const std::string& why) { std::fprintf(stderr, "trace_motorcycle_graph: %s\n", why.c_str()); return EXIT_FAILURE; }

// traces the separatrices of `uv` and prints how they ended; the graph's status is not SUCCESS if the map cannot be traced
static SS::Motorcycle_graph<Mesh> trace(const char* label, const Mesh& mesh, UV_map uv, std::size_t& inexact)
{
  const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(SS::Isoline_tracer<Mesh, UV_map>(mesh, uv));
  if(g.status != SS::SUCCESS) { std::printf("%s: cannot trace: %s\n", label, g.message.c_str()); return g; }
  inexact = 0;
  for(const auto& s : g.separatrices) inexact += s.inexact_transfers;
  std::printf("%s: %zu cones, %zu separatrices, %zu failed, %zu inexact cut crossings\n", label, g.cones,
              g.separatrices.size(), g.failed, inexact);
  for(int e = 0; e < SS::number_of_trace_ends; ++e)
    if(g.ends[e]) std::printf("  %-32s %zu%s\n", SS::trace_end_name(SS::Trace_end(e)), g.ends[e],
                              SS::is_failure(SS::Trace_end(e)) ? "  (failure)" : "");
  return g;
}

int main(int argc, char** argv)
{
  if(argc < 2) return fail("usage: trace_motorcycle_graph IN.obj [OUT.svg]");
  Mesh mesh;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(argv[1], mesh, uv, msg) != SS::SUCCESS) return fail(msg);
  UV_map input = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv_input").first;
  for(Mesh::Halfedge_index h : mesh.halfedges()) put(input, h, get(uv, h));

  const SS::Snap_report r = SS::snap_seamless_parameterization(mesh, uv);
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);

  std::size_t inexact = 0;
  trace("input  ", mesh, input, inexact);   // for comparison only: its inexact crossings and failures are what snapping removes
  const SS::Motorcycle_graph<Mesh> g = trace("snapped", mesh, uv, inexact);
  if(g.status != SS::SUCCESS) return fail("the snapped map cannot be traced");
  if(g.failed != 0 || inexact != 0) return fail("a separatrix of the snapped map failed or crossed a cut inexactly");

  if(argc > 2) {
    std::ofstream os(argv[2]);
    SS::IO::write_motorcycle_graph_svg(os, mesh, uv, g);
    if(!os) return fail(std::string("cannot write ") + argv[2]);
    std::printf("wrote %s\n", argv[2]);
  }
  return EXIT_SUCCESS;
}
