// Point in polyhedron, single-threaded: 1,000,000 points uniform in the bounding box of a closed
// mesh of ~100k triangles (../shared/corpus/meshes/armadillo.obj, 86,482 triangles; without
// ../shared, scenes::torus(1, 0.4, 400, 110): 88,000 triangles), through
//   contain  inside::MeshIndex (exact: perturbed +x ray parity over a grid of settled cells;
//            batch call on 1 thread),
//   embree   Embree 3 ray parity: one rtcIntersect1 per point along +x with an intersection
//            filter that counts every hit and rejects it, so one traversal sees all hits
//            (float32, not exact: a ray through an edge may count 0 or 2),
//   cgal     CGAL::Side_of_triangle_mesh on a Surface_mesh, Exact_predicates_inexact_
//            constructions_kernel (AABB tree, exact predicates, random re-cast on degeneracy).
// Build (preparation) times are reported apart from query times; query times are the best of
// three runs of thread CPU time (the 2-core machine is shared). Answers are compared outside the
// timed loops with contain's; a uniform point on the surface has probability ~0, so "inside" is
// compared with location == inside. Usage: point_in_mesh_bench [mesh file] [points] [cells per
// triangle] [contain-only] (the last to profile contain alone).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "contain/io/mesh_io.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_EMBREE
#include "bench/peers/embree_parity.h"

#include <limits>
#endif

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#endif

namespace {

using contain::Location;
using contain::Mesh;
using contain::Vec3;

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double timed(const std::function<void()>& f) {
  const double t0 = thread_seconds();
  f();
  return thread_seconds() - t0;
}

double best_of_three(const std::function<void()>& f) {
  double best = 1e300;
  for (int r = 0; r < 3; ++r)
    best = std::min(best, timed(f));
  return best;
}

struct Row {
  std::string name;
  double build = 0.0;
  double query = 0.0;
  std::size_t mismatches = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1] : CONTAIN_SHARED_DIR "/corpus/meshes/armadillo.obj";
  const std::size_t count = argc > 2 ? std::stoul(argv[2]) : 1'000'000;
  Mesh mesh;
  if (auto file = contain::io::read_mesh(path)) {
    mesh = std::move(file->mesh);
  } else {
    std::fprintf(stderr, "%s; using the built-in torus\n", file.error().what().c_str());
    path = "scenes::torus(1, 0.4, 400, 110)";
    mesh = contain::scenes::torus(1.0, 0.4, 400, 110);
  }
  contain::inside::MeshIndexOptions options;
  if (argc > 3) options.cells_per_triangle = std::stod(argv[3]);
  contain::inside::MeshIndex index;
  const double contain_build = timed([&] { index = contain::inside::MeshIndex(mesh, options); });
  const std::vector<Vec3> points = contain::scenes::uniform_points(index.bounds(), count, 1);
  std::vector<Location> truth(points.size());
  std::vector<Row> rows;
  {
    Row row{"contain MeshIndex (exact)", contain_build};
    row.query = best_of_three([&] { index.locate(points, truth, {.threads = 1}); });
    rows.push_back(row);
  }
  const auto st = index.stats();
  std::size_t in_surface_cells = 0;
  std::size_t inside = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    inside += truth[i] == Location::inside;
  (void)in_surface_cells;

  const bool peers = !(argc > 4 && std::string(argv[4]) == "contain-only");
#ifdef CONTAIN_BENCH_HAS_EMBREE
  if (peers) {
    Row row{"Embree 3 ray parity (float)"};
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);
    row.build = timed([&] {
      RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                            RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                            mesh.vertices.size()));
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        v[3 * i] = static_cast<float>(mesh.vertices[i].x);
        v[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
        v[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
      }
      auto* f = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  3 * sizeof(unsigned), mesh.triangles.size()));
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
          f[3 * t + static_cast<std::size_t>(k)] =
              static_cast<unsigned>(mesh.triangles[t][static_cast<std::size_t>(k)]);
      rtcSetGeometryIntersectFilterFunction(geometry, contain::bench::count_and_reject);
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene, geometry);
      rtcReleaseGeometry(geometry);
      rtcCommitScene(scene);
    });
    std::vector<char> answer(points.size());
    row.query = best_of_three([&] {
      for (std::size_t i = 0; i < points.size(); ++i) {
        answer[i] = static_cast<char>(
            contain::bench::odd_crossings(scene, points[i].x, points[i].y, points[i].z));
      }
    });
    for (std::size_t i = 0; i < points.size(); ++i)
      row.mismatches += (answer[i] != 0) != (truth[i] == Location::inside);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    rows.push_back(row);
  }
#endif

#ifdef CONTAIN_BENCH_HAS_CGAL
  if (peers) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
    Row row{"CGAL Side_of_triangle_mesh (EPICK)"};
    SurfaceMesh sm;
    std::vector<SurfaceMesh::Vertex_index> vi;
    for (const Vec3& p : mesh.vertices)
      vi.push_back(sm.add_vertex(K::Point_3(p.x, p.y, p.z)));
    for (const auto& t : mesh.triangles)
      sm.add_face(vi[static_cast<std::size_t>(t[0])], vi[static_cast<std::size_t>(t[1])],
                  vi[static_cast<std::size_t>(t[2])]);
    std::unique_ptr<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>> side;
    row.build = timed([&] {
      side = std::make_unique<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>>(sm);
      (void)(*side)(K::Point_3(points[0].x, points[0].y, points[0].z));  // builds the tree
    });
    std::vector<char> answer(points.size());
    row.query = best_of_three([&] {
      for (std::size_t i = 0; i < points.size(); ++i) {
        answer[i] =
            (*side)(K::Point_3(points[i].x, points[i].y, points[i].z)) == CGAL::ON_BOUNDED_SIDE;
      }
    });
    for (std::size_t i = 0; i < points.size(); ++i)
      row.mismatches += (answer[i] != 0) != (truth[i] == Location::inside);
    rows.push_back(row);
  }
#endif

  std::printf(
      "mesh %s: %zu triangles, regime %s; %zu points uniform in its bounding box, %zu inside\n",
      path.c_str(), mesh.triangles.size(), to_string(index.regime()), points.size(), inside);
  std::printf(
      "contain grid %d x %d x %d = %zu cells, %zu surface cells (%.1f%%), %zu triangle refs\n",
      st.nx, st.ny, st.nz, st.cells, st.surface_cells,
      100.0 * static_cast<double>(st.surface_cells) /
          static_cast<double>(std::max<std::size_t>(st.cells, 1)),
      st.cell_refs);
  std::printf("%-36s %10s %10s %12s %12s %10s\n", "method (1 thread)", "build s", "query s",
              "points/s", "x contain", "mismatch");
  for (const Row& r : rows) {
    std::printf("%-36s %10.4f %10.4f %12.3e %12.2f %10zu\n", r.name.c_str(), r.build, r.query,
                static_cast<double>(points.size()) / r.query, r.query / rows.front().query,
                r.mismatches);
  }
  return 0;
}
