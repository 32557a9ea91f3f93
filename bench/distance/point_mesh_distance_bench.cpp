// Signed distance from points to a closed mesh, single-threaded: 10^6 points uniform in the
// bounding box of a closed mesh (../shared/corpus/meshes/armadillo.obj, 86,482 triangles, or
// the file given; a generated torus of exactly 100,000 triangles as the second scene), through
//   contain  distance::MeshDistance, signed (sign from inside::MeshIndex, exact), the distance
//            rounded once, the closest point rounded per coordinate and the closest triangle
//            (batch call on 1 thread); and the same without the closest point;
//   cgal     CGAL 5.5 AABB_tree over the Surface_mesh faces (Epick, accelerate_distance_queries)
//            squared_distance(p), then sqrt, plus CGAL::Side_of_triangle_mesh sharing the same
//            tree for the sign (floating-point distance; exact predicates for the side test).
// Build and query times are thread CPU seconds of one run each (the 2-core machine is shared).
// Answers are compared outside the timed loops: signs must agree (uniform points are on the
// surface with probability ~0), distances within 1e-12 relative (CGAL's are not rounded once).
// Usage: point_mesh_distance_bench [mesh file] [points] [contain-only]

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "contain/distance/mesh_distance.h"
#include "contain/io/mesh_io.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#endif

namespace {

using contain::Mesh;
using contain::Vec3;
using contain::distance::Closest3;

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

// Indices sorted by the Morton code of the points quantised to 1024 cells per axis.
[[maybe_unused]] std::vector<std::size_t> morton(const std::vector<Vec3>& points) {
  contain::Box3 box;
  for (const Vec3& p : points)
    box.expand(p);
  auto spread = [](std::uint64_t x) {
    std::uint64_t r = 0;
    for (int b = 0; b < 10; ++b)
      r |= ((x >> b) & 1U) << (3 * b);
    return r;
  };
  auto cell = [](double x, double lo, double hi) {
    const double t = (x - lo) / (hi - lo) * 1024;
    return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1023.0));
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    keyed.push_back({spread(cell(p.x, box.min.x, box.max.x)) |
                         (spread(cell(p.y, box.min.y, box.max.y)) << 1) |
                         (spread(cell(p.z, box.min.z, box.max.z)) << 2),
                     i});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> order;
  for (const auto& k : keyed)
    order.push_back(k.second);
  return order;
}

struct Row {
  std::string name;
  double build = 0.0;
  double query = 0.0;
  std::size_t sign_mismatches = 0;
  std::size_t distance_mismatches = 0;
};

void run(const std::string& name, const Mesh& mesh, std::size_t count, bool peers) {
  std::vector<Row> rows;
  contain::distance::MeshDistance prepared;
  const double build = timed([&] { prepared = contain::distance::MeshDistance(mesh); });
  const std::vector<Vec3> points =
      contain::scenes::uniform_points(prepared.index().bounds(), count, 1);
  std::vector<Closest3> truth(points.size());
  contain::distance::MeshDistanceStats stats;
  {
    Row row{"contain signed + closest point + triangle", build};
    row.query = timed([&] {
      stats =
          prepared.distance_with_stats(points, truth, {.signed_distance = true}, {.threads = 1});
    });
    rows.push_back(row);
  }
  {
    std::vector<Closest3> plain(points.size());
    Row row{"contain signed distance only", build};
    row.query = timed([&] {
      prepared.distance(points, plain, {.signed_distance = true, .closest_point = false},
                        {.threads = 1});
    });
    for (std::size_t i = 0; i < points.size(); ++i)
      row.distance_mismatches += plain[i].distance != truth[i].distance;
    rows.push_back(row);
  }
  std::size_t inside = 0;
  for (const Closest3& c : truth)
    inside += c.location == contain::Location::inside;
#ifdef CONTAIN_BENCH_HAS_CGAL
  if (peers) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
    SurfaceMesh sm;
    std::vector<SurfaceMesh::Vertex_index> vi;
    for (const Vec3& p : mesh.vertices)
      vi.push_back(sm.add_vertex(K::Point_3(p.x, p.y, p.z)));
    for (const auto& t : mesh.triangles)
      sm.add_face(vi[static_cast<std::size_t>(t[0])], vi[static_cast<std::size_t>(t[1])],
                  vi[static_cast<std::size_t>(t[2])]);
    Row row{"CGAL AABB_tree + Side_of_triangle_mesh"};
    std::unique_ptr<Tree> tree;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>> side;
    row.build = timed([&] {
      tree = std::make_unique<Tree>(faces(sm).first, faces(sm).second, sm);
      tree->build();
      tree->accelerate_distance_queries();
      side = std::make_unique<CGAL::Side_of_triangle_mesh<SurfaceMesh, K>>(*tree);
    });
    std::vector<double> answer(points.size());
    row.query = timed([&] {
      for (std::size_t i = 0; i < points.size(); ++i) {
        const K::Point_3 q(points[i].x, points[i].y, points[i].z);
        const double d = std::sqrt(CGAL::to_double(tree->squared_distance(q)));
        answer[i] = (*side)(q) == CGAL::ON_BOUNDED_SIDE ? -d : d;
      }
    });
    for (std::size_t i = 0; i < points.size(); ++i) {
      row.sign_mismatches += (answer[i] < 0) != (truth[i].distance < 0);
      row.distance_mismatches += std::fabs(std::fabs(answer[i]) - std::fabs(truth[i].distance)) >
                                 1e-12 * std::max(1.0, std::fabs(truth[i].distance));
    }
    rows.push_back(row);
    // The same in the order contain's batch uses (Morton order of the points), so that cache
    // effects of the order are not counted in contain's favour.
    const std::vector<std::size_t> order = morton(points);
    Row sorted{"CGAL, the same in Morton order", row.build};
    sorted.query = timed([&] {
      for (const std::size_t i : order) {
        const K::Point_3 q(points[i].x, points[i].y, points[i].z);
        const double d = std::sqrt(CGAL::to_double(tree->squared_distance(q)));
        answer[i] = (*side)(q) == CGAL::ON_BOUNDED_SIDE ? -d : d;
      }
    });
    for (std::size_t i = 0; i < points.size(); ++i)
      sorted.sign_mismatches += (answer[i] < 0) != (truth[i].distance < 0);
    rows.push_back(sorted);
  }
#else
  (void)peers;
#endif
  std::printf(
      "mesh %s: %zu triangles, regime %s; %zu points uniform in its bounding box, %zu inside\n",
      name.c_str(), mesh.triangles.size(), to_string(prepared.regime()), points.size(), inside);
  std::printf(
      "contain per query: %.1f nodes, %.1f triangles bounded (%.1f by the cheap tests alone), "
      "%.2f contenders, %.3f exact comparisons, %.2f settled by a shared feature\n",
      static_cast<double>(stats.nodes) / static_cast<double>(stats.queries),
      static_cast<double>(stats.triangles) / static_cast<double>(stats.queries),
      static_cast<double>(stats.cheap) / static_cast<double>(stats.queries),
      static_cast<double>(stats.contenders) / static_cast<double>(stats.queries),
      static_cast<double>(stats.exact_comparisons) / static_cast<double>(stats.queries),
      static_cast<double>(stats.shared_features) / static_cast<double>(stats.queries));
  std::printf("%-44s %9s %9s %12s %10s %6s %6s\n", "method (1 thread)", "build s", "query s",
              "points/s", "x contain", "sign", "dist");
  for (const Row& r : rows) {
    std::printf("%-44s %9.4f %9.4f %12.3e %10.2f %6zu %6zu\n", r.name.c_str(), r.build, r.query,
                static_cast<double>(points.size()) / r.query, r.query / rows.front().query,
                r.sign_mismatches, r.distance_mismatches);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : CONTAIN_SHARED_DIR "/corpus/meshes/armadillo.obj";
  const std::size_t count = argc > 2 ? std::stoul(argv[2]) : 1'000'000;
  const bool peers = !(argc > 3 && std::string(argv[3]) == "contain-only");
  if (auto file = contain::io::read_mesh(path)) {
    run(path, file->mesh, count, peers);
  } else {
    std::fprintf(stderr, "%s; skipping the file scene\n", file.error().what().c_str());
  }
  run("scenes::torus(1, 0.4, 500, 100) (100,000 triangles)",
      contain::scenes::torus(1.0, 0.4, 500, 100), count, peers);
  return 0;
}
