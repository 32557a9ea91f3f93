#include "contain/distance/point_primitive.h"

#include <algorithm>
#include <array>

#include "contain/predicates/closest_feature.h"
#include "distance/flat_answer.h"

namespace contain::distance {

using predicates::FlatPair3;
using predicates::point_flat;

Closest3 point_triangle(const Triangle3& t, Vec3 p) {
  const predicates::TriangleFeature f = predicates::closest_feature(t, p);
  return detail::answer({point_flat(p), predicates::feature_flat(t, f)}, true);
}

Closest3 point_segment(const Segment3& s, Vec3 p) {
  const predicates::SegmentFeature f = predicates::closest_feature(s, p);
  return detail::answer({point_flat(p), predicates::feature_flat(s, f)}, true);
}

Closest2 point_segment(const Segment2& s, Vec2 p) {
  const predicates::SegmentFeature f = predicates::closest_feature(s, p);
  return detail::answer({predicates::point_flat(p), predicates::feature_flat(s, f)}, true);
}

Closest3 point_box(const Box3& box, Vec3 p, const PointQuery& query) {
  const Vec3 clamped{std::clamp(p.x, box.min.x, box.max.x), std::clamp(p.y, box.min.y, box.max.y),
                     std::clamp(p.z, box.min.z, box.max.z)};
  if (!(clamped == p)) {  // outside: the clamped point is the closest point of the solid box
    Closest3 out = detail::answer({point_flat(p), point_flat(clamped)}, false);
    out.point = clamped;
    if (query.signed_distance) out.location = Location::outside;
    return out;
  }
  // Inside or on the surface: the nearest of the six faces, by exact comparisons of the
  // differences (each a point-point distance along one axis); ties keep the lowest face.
  const std::array<Vec3, 6> foot{Vec3{box.min.x, p.y, p.z}, Vec3{box.max.x, p.y, p.z},
                                 Vec3{p.x, box.min.y, p.z}, Vec3{p.x, box.max.y, p.z},
                                 Vec3{p.x, p.y, box.min.z}, Vec3{p.x, p.y, box.max.z}};
  int best = 0;
  for (int f = 1; f < 6; ++f) {
    const FlatPair3 candidate{point_flat(p), point_flat(foot[static_cast<std::size_t>(f)])};
    const FlatPair3 current{point_flat(p), point_flat(foot[static_cast<std::size_t>(best)])};
    if (predicates::compare_squared_distances(candidate, current) == Sign::negative) best = f;
  }
  const Vec3 q = foot[static_cast<std::size_t>(best)];
  Closest3 out = detail::answer({point_flat(p), point_flat(q)}, false);
  out.point = q;
  out.feature = best;
  if (query.signed_distance) {
    detail::apply_sign(out, q == p ? Location::boundary : Location::inside);
  }
  return out;
}

}  // namespace contain::distance
