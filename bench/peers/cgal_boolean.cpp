// CGAL's corefinement boolean with the exact-constructions kernel, as its users call it, as a
// whole process for the solids benchmark (issue 25): read two OFF files (CGAL's reader), A op B
// by Polygon_mesh_processing::corefine_and_compute_{union,intersection,difference}, write OFF
// (CGAL's writer, 17 digits).
// Usage: cgal_boolean A.off B.off --op union|intersection|difference OUT.off
// CGAL 5.5 (Debian libcgal-dev), Surface_mesh over Epeck points, one thread. On stderr, the
// kernel time of the corefine-and-compute call alone; reading and writing are outside it.

#include <cstdio>
#include <optional>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include "bench/peers/peer_driver.h"

using namespace contain::bench;

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// corefine_and_compute_* refines both inputs in place (their shared curves become edges of both).
bool apply(SurfaceMesh& a, SurfaceMesh& b, BooleanOp op, SurfaceMesh& out) {
  switch (op) {
    case BooleanOp::union_:
      return PMP::corefine_and_compute_union(a, b, out);
    case BooleanOp::intersection:
      return PMP::corefine_and_compute_intersection(a, b, out);
    case BooleanOp::difference:
      return PMP::corefine_and_compute_difference(a, b, out);
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<BooleanArgs> args = parse_boolean_args(argc, argv);
  if (!args) {
    std::fprintf(stderr,
                 "usage: cgal_boolean A.off B.off --op union|intersection|difference OUT.off\n");
    return 2;
  }
  SurfaceMesh a;
  SurfaceMesh b;
  if (!CGAL::IO::read_polygon_mesh(args->a, a) || !CGAL::IO::read_polygon_mesh(args->b, b)) {
    std::fprintf(stderr, "cgal_boolean: cannot read %s or %s as a polygon mesh\n", args->a.c_str(),
                 args->b.c_str());
    return 3;
  }

  SurfaceMesh out;
  const KernelClock clock;
  const bool done = apply(a, b, args->op, out);
  clock.report("boolean");
  if (!done) {
    std::fprintf(stderr, "cgal_boolean: the result is not representable as a closed mesh\n");
    return 1;
  }
  if (!CGAL::IO::write_polygon_mesh(args->out, out, CGAL::parameters::stream_precision(17))) {
    std::fprintf(stderr, "cgal_boolean: cannot write %s\n", args->out.c_str());
    return 3;
  }
  std::printf("%zu triangles\n", static_cast<std::size_t>(out.number_of_faces()));
  return 0;
}
