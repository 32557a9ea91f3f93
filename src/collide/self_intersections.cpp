#include "contain/collide/self_intersections.h"

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "contain/bvh/triangle_boxes.h"
#include "contain/collide/tri_tri.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient3d.h"

// Outline: a hierarchy over the triangles' boxes, traversed against itself; each pair of
// distinct, non-degenerate triangles with overlapping boxes is decided by the corners the two
// share (by coordinates) and the exact segment-triangle tests derived in the header.

namespace contain::collide {
namespace {

// Corner k of `t`, in index order.
const Vec3& corner(const Triangle3& t, int k) {
  return k == 0 ? t.a : k == 1 ? t.b : t.c;
}

// A segment as the flat triangle spanned by it (segment_triangle takes degenerate
// triangles as their segment hull).
Triangle3 flat(const Vec3& p, const Vec3& q) {
  return {p, q, q};
}

// Whether non-degenerate a and b (corners pairwise distinct within each) share a point besides
// the corners they share.
bool meet_beyond_shared(const Triangle3& a, const Triangle3& b) {
  std::array<int, 3> in_b{-1, -1, -1};  // corner k of a is corner in_b[k] of b
  int shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (corner(a, i) == corner(b, j)) {
        in_b[static_cast<std::size_t>(i)] = j;
        ++shared;
      }
    }
  }
  if (shared == 0) return tri_tri(a, b);
  if (shared == 3) return false;  // a duplicated triangle: validate_mesh's finding
  if (shared == 1) {
    // P shared; the edges opposite P in a and in b.
    int pa = 0;
    while (in_b[static_cast<std::size_t>(pa)] < 0)
      ++pa;
    const int pb = in_b[static_cast<std::size_t>(pa)];
    const Segment3 far_a{corner(a, (pa + 1) % 3), corner(a, (pa + 2) % 3)};
    const Segment3 far_b{corner(b, (pb + 1) % 3), corner(b, (pb + 2) % 3)};
    return segment_triangle(far_a, b) || segment_triangle(far_b, a);
  }
  // Edge P Q shared: a = P Q a2, b = P Q b2 (as points; the index order does not matter).
  int ra = 0;
  while (in_b[static_cast<std::size_t>(ra)] >= 0)
    ++ra;
  const Vec3& a2 = corner(a, ra);
  const Vec3& p = corner(a, (ra + 1) % 3);
  const Vec3& q = corner(a, (ra + 2) % 3);
  const Vec3* b2 = nullptr;
  for (int j = 0; j < 3; ++j) {
    if (!(corner(b, j) == p) && !(corner(b, j) == q)) b2 = &corner(b, j);
  }
  // Not coplanar (the usual neighbours): the planes meet in the line P Q, which holds a ∩ b,
  // and each triangle meets that line in the edge P Q only. One orient3d.
  if (predicates::orient3d(p, q, a2, *b2) != Sign::zero) return false;
  return segment_triangle({a2, a2}, b) || segment_triangle({*b2, *b2}, a) ||
         segment_triangle({q, a2}, flat(p, *b2)) || segment_triangle({p, a2}, flat(q, *b2));
}

}  // namespace

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
        if (!meet_beyond_shared(triangles[si], triangles[sj])) return bvh::Visit::proceed;
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
