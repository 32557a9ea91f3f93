#include "contain/inside/point_in_convex.h"

#include "contain/predicates/orient3d.h"
#include "contain/predicates/side_of_plane.h"

namespace contain::inside {

Location point_in_convex(const ConvexPolyhedron& polyhedron, Vec3 p) {
  Location result = Location::inside;
  for (const Plane& plane : polyhedron.planes()) {
    const Sign s = predicates::side_of_plane(plane, p);
    if (s == Sign::negative) return Location::outside;
    if (s == Sign::zero) result = Location::boundary;
  }
  for (const Triangle3& face : polyhedron.faces()) {
    // Positive inside the face (counter-clockwise from outside), zero on its plane.
    const Sign s = -predicates::orient3d(face.a, face.b, face.c, p);
    if (s == Sign::negative) return Location::outside;
    if (s == Sign::zero) result = Location::boundary;
  }
  return result;
}

void point_in_convex(const ConvexPolyhedron& polyhedron, std::span<const Vec3> points,
                     std::span<Location> out, const BatchOptions& options) {
  parallel_for(points.size(), options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = point_in_convex(polyhedron, points[i]);
  });
}

}  // namespace contain::inside
