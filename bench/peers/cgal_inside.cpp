// Whole-process peer of `contain inside --mesh M.off --points PTS --threads 1`: reads the OFF
// and the points (peer_points.h), builds a CGAL Surface_mesh and Side_of_triangle_mesh (EPICK,
// its AABB tree built on the first query) and answers in, on or out for each point. Kernel
// times on stderr.
//   cgal_inside MESH.off POINTS.txt > answers.txt

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <vector>

#include "bench/peers/peer_driver.h"
#include "bench/peers/peer_points.h"

int main(int argc, char** argv) {
  using namespace contain::bench;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
  if (argc != 3) {
    std::fprintf(stderr, "usage: cgal_inside MESH.off POINTS.txt\n");
    return 2;
  }
  const OffMesh mesh = read_off(argv[1]);
  const std::vector<double> xyz = read_numbers(argv[2]);
  const KernelClock build_clock;
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> vi;
  vi.reserve(mesh.vertices.size() / 3);
  for (std::size_t i = 0; i < mesh.vertices.size(); i += 3)
    vi.push_back(
        sm.add_vertex(K::Point_3(mesh.vertices[i], mesh.vertices[i + 1], mesh.vertices[i + 2])));
  for (std::size_t i = 0; i < mesh.triangles.size(); i += 3)
    sm.add_face(vi[mesh.triangles[i]], vi[mesh.triangles[i + 1]], vi[mesh.triangles[i + 2]]);
  const CGAL::Side_of_triangle_mesh<SurfaceMesh, K> side(sm);
  std::vector<signed char> answers(xyz.size() / 3);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const CGAL::Bounded_side s = side(K::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
    answers[i] = s == CGAL::ON_BOUNDED_SIDE ? 1 : s == CGAL::ON_BOUNDARY ? 0 : -1;
  }
  build_clock.report("build + query");
  write_answers(answers);
  return 0;
}
