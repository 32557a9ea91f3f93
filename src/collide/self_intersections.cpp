#include "contain/collide/self_intersections.h"

#include <cstddef>
#include <utility>
#include <vector>

#include "contain/bvh/triangle_boxes.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/triangles_meet.h"

// Outline: a hierarchy over the triangles' boxes, traversed against itself; each pair of
// distinct, non-degenerate triangles with overlapping boxes is decided by the corners the two
// share (by coordinates) and exact segment-triangle tests: predicates::triangles_meet_beyond_shared
// (a triangle twice, three corners shared, is validate_mesh's finding, not a crossing here).

namespace contain::collide {

SelfIntersections self_intersections(const Mesh& mesh, const SelfIntersectionsOptions& options) {
  SelfIntersections found;
  const std::size_t n = mesh.triangles.size();
  std::vector<Triangle3> triangles(n);
  std::vector<bool> degenerate(n);
  for (std::size_t t = 0; t < n; ++t) {
    triangles[t] = mesh.triangle(t);
    degenerate[t] = predicates::collinear(triangles[t].a, triangles[t].b, triangles[t].c);
  }
  const std::vector<Box3> boxes = bvh::triangle_boxes(mesh);
  const bvh::Bvh tree(boxes, options.bvh);
  const bvh::TraversalStats stats = bvh::traverse_self(
      tree, [](const bvh::Node& x, const bvh::Node& y) { return x.box.overlaps(y.box); },
      [&](std::int32_t i, std::int32_t j) {
        if (i > j) std::swap(i, j);
        const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
        if (degenerate[si] || degenerate[sj] || !boxes[si].overlaps(boxes[sj])) {
          return bvh::Visit::proceed;
        }
        if (!predicates::triangles_meet_beyond_shared(triangles[si], triangles[sj]))
          return bvh::Visit::proceed;
        if (found.pairs.size() < options.keep) found.pairs.push_back({i, j});
        ++found.count;
        if (options.limit != 0 && found.count >= options.limit) return bvh::Visit::stop;
        return bvh::Visit::proceed;
      });
  found.stopped = stats.stopped;
  found.node_pairs = stats.nodes;
  return found;
}

}  // namespace contain::collide
