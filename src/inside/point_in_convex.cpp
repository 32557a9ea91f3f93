#include "contain/inside/point_in_convex.h"

#include "contain/predicates/orient3d.h"
#include "contain/predicates/side_of_plane.h"

namespace contain::inside {
namespace {

// The part of a location that one face decides: positive inside the face (counter-clockwise
// from outside), zero on its plane. False when p is outside.
bool inside_face(Vec3 a, Vec3 b, Vec3 c, Vec3 p, Location& result) {
  const Sign s = -predicates::orient3d(a, b, c, p);
  if (s == Sign::zero) result = Location::boundary;
  return s != Sign::negative;
}

}  // namespace

Location point_in_convex(const ConvexPolyhedron& polyhedron, Vec3 p) {
  Location result = Location::inside;
  for (const Plane& plane : polyhedron.planes()) {
    const Sign s = predicates::side_of_plane(plane, p);
    if (s == Sign::negative) return Location::outside;
    if (s == Sign::zero) result = Location::boundary;
  }
  for (const Triangle3& face : polyhedron.faces())
    if (!inside_face(face.a, face.b, face.c, p, result)) return Location::outside;
  return result;
}

Location point_in_convex(const ConvexPolyhedron& polyhedron, std::span<const Vec3> placed, Vec3 p) {
  Location result = Location::inside;
  for (const TriangleIndices& t : polyhedron.face_indices()) {
    if (!inside_face(placed[static_cast<std::size_t>(t[0])], placed[static_cast<std::size_t>(t[1])],
                     placed[static_cast<std::size_t>(t[2])], p, result))
      return Location::outside;
  }
  return result;
}

void point_in_convex(const ConvexPolyhedron& polyhedron, std::span<const Vec3> points,
                     std::span<Location> out, const BatchOptions& options) {
  batch_map(points, out, options, 4096, [&](Vec3 p) { return point_in_convex(polyhedron, p); });
}

}  // namespace contain::inside
