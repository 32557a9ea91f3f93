#include "contain/clip/clip_point.h"

#include "contain/inside/point_in_convex.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/compare_distance.h"
#include "contain/predicates/side_of_plane.h"

namespace contain::clip {
namespace {

template <class V>
std::optional<V> keep_if(bool in, V p) {
  if (in) return p;
  return std::nullopt;
}

}  // namespace

std::optional<Vec3> clip_point(Vec3 p, const Box3& box) {
  return keep_if(box.contains(p), p);
}
std::optional<Vec2> clip_point(Vec2 p, const Box2& box) {
  return keep_if(box.contains(p), p);
}
std::optional<Vec3> clip_point(Vec3 p, const Plane& half_space) {
  return keep_if(predicates::side_of_plane(half_space, p) != Sign::negative, p);
}
std::optional<Vec2> clip_point(Vec2 p, const HalfPlane& half_plane) {
  return keep_if(predicates::side_of_line(half_plane, p) != Sign::negative, p);
}
std::optional<Vec3> clip_point(Vec3 p, const Sphere& ball) {
  return keep_if(predicates::side_of_sphere(ball, p) != Sign::negative, p);
}
std::optional<Vec2> clip_point(Vec2 p, const Circle& disc) {
  return keep_if(predicates::side_of_circle(disc, p) != Sign::negative, p);
}
std::optional<Vec3> clip_point(Vec3 p, const ConvexPolyhedron& polyhedron) {
  return keep_if(inside::point_in_convex(polyhedron, p) != Location::outside, p);
}
std::optional<Vec2> clip_point(Vec2 p, const Polygon& polygon) {
  return keep_if(inside::point_in_polygon(polygon, p) != Location::outside, p);
}

}  // namespace contain::clip
