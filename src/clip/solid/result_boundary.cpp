// Vertices of a written mesh proven near the exact result's boundary (result_boundary.h).
//
// Inputs snapped on grids of up to 2^28 ulps move their vertices by up to 1.2e-7 of the largest
// coordinate, far beyond the 1e-9 the engine promises; such a result is kept only when each of
// its vertices is shown to be within the promise of the exact result's boundary. The distance
// from a point of doubles to a triangle of doubles is decided exactly (the feature holding the
// closest point, then the sign of its squared distance minus the bound's square); the exact
// boundary's corners are implicit points, so their nearest doubles stand in for them and the
// bound shrinks by the most rounding can move a triangle.

#include "clip/solid/result_boundary.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/squared_distance.h"
#include "contain/values/box.h"
#include "contain/values/triangle.h"

namespace contain::clip::solid {
namespace {

bool near_triangle(const Triangle3& t, Vec3 p, double reach) {
  const predicates::TriangleFeature f = predicates::closest_feature(t, p);
  const predicates::FlatPair3 pair{predicates::point_flat(p), predicates::feature_flat(t, f)};
  return predicates::compare_squared_distance(pair, reach) != Sign::positive;
}

}  // namespace

bool within_boundary(const Mesh& mesh, std::span<const std::array<std::int32_t, 3>> faces,
                     const PointStore& store, double bound, double scale) {
  if (mesh.vertices.empty()) return true;
  // The bound less one ulp of scale (more than sqrt(3)/2 of it), and less a relative 2^-50 for
  // the roundings of these two operations: a distance proven within `reach` of a rounded face is
  // within `bound` of the exact face.
  const double ulp = std::nextafter(scale, std::numeric_limits<double>::infinity()) - scale;
  const double reach = bound * (1.0 - std::ldexp(1.0, -50)) - ulp;
  if (!(reach > 0.0)) return false;
  std::vector<Triangle3> triangles;
  std::vector<Box3> boxes;
  triangles.reserve(faces.size());
  boxes.reserve(faces.size());
  for (const auto& f : faces) {
    const Triangle3 t{store.rounded(f[0]), store.rounded(f[1]), store.rounded(f[2])};
    triangles.push_back(t);
    boxes.push_back(bounding_box(t));
  }
  if (triangles.empty()) return false;
  const bvh::Bvh tree(boxes);
  for (const Vec3 p : mesh.vertices) {
    // Candidates: faces whose boxes meet p's box of twice the reach (a box rounded inward by
    // the subtractions still holds every face within reach).
    const Vec3 r{2 * reach, 2 * reach, 2 * reach};
    const Box3 around{p - r, p + r};
    const bvh::TraversalStats seen = tree.traverse(
        [&](const bvh::Node& node, std::int32_t) { return node.box.overlaps(around); },
        [&](std::int32_t i) {
          const auto k = static_cast<std::size_t>(i);
          return boxes[k].overlaps(around) && near_triangle(triangles[k], p, reach)
                     ? bvh::Visit::stop
                     : bvh::Visit::proceed;
        });
    if (!seen.stopped) return false;
  }
  return true;
}

}  // namespace contain::clip::solid
