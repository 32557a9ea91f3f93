// CGAL's Polygon_mesh_slicer as its users call it, as a whole process for the slicing benchmark
// (issue 26): read an OFF file (CGAL's reader), cut it by N evenly spaced planes perpendicular
// to an axis (the middles of N equal layers of its extent, as every driver and contain), print
// per plane the value, the number of polylines and the area they enclose.
// Usage: cgal_slice MESH.off [--planes N] [--axis x|y|z]      (defaults: 100, z)
// CGAL 5.5 (Debian libcgal-dev), Surface_mesh over Epick points, one thread. The slicer gives
// polylines only (no regions, no nesting): the area printed is the sum of |shoelace area| over
// the closed ones, which is the section's area only where no ring lies inside another. On
// stderr, the kernel times: the slicer's construction and the N slices (its AABB tree of edges
// is built lazily, so inside the first slice).

#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>

#include "bench/peers/peer_driver.h"

using namespace contain::bench;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Polyline = std::vector<Point>;

double enclosed_area(const std::vector<Polyline>& polylines, int axis) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  double total = 0.0;
  for (const Polyline& line : polylines) {
    if (line.size() < 4 || line.front() != line.back()) continue;
    double twice = 0.0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      twice += line[i][u] * line[i + 1][v] - line[i + 1][u] * line[i][v];
    }
    total += std::abs(twice) / 2.0;
  }
  return total;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<SliceArgs> args = parse_slice_args(argc, argv);
  if (!args) {
    std::fprintf(stderr, "usage: cgal_slice MESH.off [--planes N] [--axis x|y|z]\n");
    return 2;
  }
  SurfaceMesh mesh;
  if (!CGAL::IO::read_polygon_mesh(args->mesh, mesh) || mesh.is_empty()) {
    std::fprintf(stderr, "cgal_slice: cannot read %s as a polygon mesh\n", args->mesh.c_str());
    return 3;
  }
  double lo = HUGE_VAL;
  double hi = -HUGE_VAL;
  for (const Point& p : mesh.points()) {
    lo = std::min(lo, p[args->axis]);
    hi = std::max(hi, p[args->axis]);
  }
  const std::vector<double> values = plane_values(lo, hi, args->planes);
  double normal[3] = {0.0, 0.0, 0.0};
  normal[args->axis] = 1.0;

  const KernelClock build_clock;
  CGAL::Polygon_mesh_slicer<SurfaceMesh, Kernel> slicer(mesh);
  build_clock.report("build");
  std::vector<std::vector<Polyline>> sections(values.size());
  const KernelClock slice_clock;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const Kernel::Plane_3 plane(normal[0], normal[1], normal[2], -values[i]);
    slicer(plane, std::back_inserter(sections[i]));
  }
  slice_clock.report("slice");

  for (std::size_t i = 0; i < values.size(); ++i) {
    std::printf("%.17g %zu %.17g\n", values[i], sections[i].size(),
                enclosed_area(sections[i], args->axis));
  }
  return 0;
}
