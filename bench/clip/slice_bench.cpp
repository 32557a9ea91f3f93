// Sections of a closed mesh by many parallel planes, contain beside CGAL, in one run:
//   sphere131k, sphere524k   UV spheres of radius 1 (256 x 256 and 512 x 512 quads, poles as
//                            fans: 130,560 and 523,264 triangles), built in this file;
//   100 / 10000 planes       z = -1 + (k + 0.5) 2 / n, k = 0..n-1 (no plane through a vertex).
// contain: clip::slice_mesh (filled regions with holes, exact, provenance per edge) on one
// thread and on every core; the time includes its closedness check and welding. CGAL 5.5
// Polygon_mesh_slicer on a Surface_mesh<Epick> (polylines only: no filling, no nesting), the
// AABB tree built inside the timed part, one call per plane. Checked outside the timed part:
// each plane gives one ring (contain) and one closed polyline (CGAL), and contain's areas sum to
// within 1e-3 of the exact sphere's sum of pi (1 - z^2) (the mesh is inscribed). Times: process
// CPU seconds and wall seconds (the 2-core machine is shared: CPU time is the measure).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <vector>

#include "contain/clip/slice_mesh.h"

#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>
#endif

namespace {

using namespace contain;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<double> planes(int n) {
  std::vector<double> out;
  for (int k = 0; k < n; ++k)
    out.push_back(-1.0 + (k + 0.5) * 2.0 / n);
  return out;
}

void run_contain(const char* scene, const Mesh& mesh, const std::vector<double>& values,
                 int threads) {
  const double c0 = cpu_seconds();
  const double w0 = wall_seconds();
  auto sections = clip::slice_mesh(mesh, values, {}, {.threads = threads});
  const double cpu = cpu_seconds() - c0;
  const double wall = wall_seconds() - w0;
  if (!sections) {
    std::printf("%s: %s\n", scene, sections.error().what().c_str());
    return;
  }
  std::size_t single = 0;
  double area = 0;
  double exact = 0;
  for (const clip::Section& s : *sections) {
    const std::vector<Ring> rings = s.region.all_rings();
    single += rings.size() == 1 ? 1 : 0;
    for (const Ring& r : rings)
      area += signed_area2(r) / 2;
    exact += std::numbers::pi * (1 - s.value * s.value);
  }
  std::printf(
      "%-11s %6zu planes  contain %-10s cpu %7.3f s  wall %7.3f s  one ring: %zu/%zu  "
      "area/exact %.6f\n",
      scene, values.size(), threads == 1 ? "1 thread" : "all cores", cpu, wall, single,
      values.size(), area / exact);
}

#ifdef CONTAIN_BENCH_HAS_CGAL
void run_cgal(const char* scene, const Mesh& mesh, const std::vector<double>& values) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  for (const Vec3& p : mesh.vertices)
    v.push_back(sm.add_vertex(K::Point_3(p.x, p.y, p.z)));
  for (const TriangleIndices& t : mesh.triangles)
    sm.add_face(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                v[static_cast<std::size_t>(t[2])]);
  const double c0 = cpu_seconds();
  const double w0 = wall_seconds();
  CGAL::Polygon_mesh_slicer<SurfaceMesh, K> slicer(sm);
  std::vector<std::vector<std::vector<K::Point_3>>> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    slicer(K::Plane_3(0, 0, 1, -values[i]), std::back_inserter(out[i]));
  const double cpu = cpu_seconds() - c0;
  const double wall = wall_seconds() - w0;
  std::size_t single = 0;
  for (const auto& polylines : out)
    single += polylines.size() == 1 ? 1 : 0;
  std::printf(
      "%-11s %6zu planes  CGAL slicer          cpu %7.3f s  wall %7.3f s  one polyline: "
      "%zu/%zu\n",
      scene, values.size(), cpu, wall, single, values.size());
}
#endif

}  // namespace

int main() {
  struct Scene {
    const char* name;
    Mesh mesh;
  };
  const Scene scenes[] = {{"sphere131k", scenes::uv_sphere({0, 0, 0}, 1.0, 256, 256)},
                          {"sphere524k", scenes::uv_sphere({0, 0, 0}, 1.0, 512, 512)}};
  for (const Scene& s : scenes) {
    for (const int n : {100, 10000}) {
      const std::vector<double> values = planes(n);
      run_contain(s.name, s.mesh, values, 1);
      run_contain(s.name, s.mesh, values, 0);
#ifdef CONTAIN_BENCH_HAS_CGAL
      run_cgal(s.name, s.mesh, values);
#endif
    }
  }
  return 0;
}
