#include "contain/inside/implicit.h"

#include "contain/predicates/compare_distance.h"
#include "contain/predicates/side_of_plane.h"

namespace contain::inside {
namespace {

Location from_sign(Sign s) {
  switch (s) {
    case Sign::positive:
      return Location::inside;
    case Sign::zero:
      return Location::boundary;
    case Sign::negative:
      break;
  }
  return Location::outside;
}

// Location of x in the closed interval [lo, hi]; comparisons of given doubles are exact.
Location in_interval(double x, double lo, double hi) {
  if (x < lo || x > hi) return Location::outside;
  if (x == lo || x == hi) return Location::boundary;
  return Location::inside;
}

}  // namespace

Location point_in_sphere(const Sphere& sphere, Vec3 p) {
  return from_sign(predicates::side_of_sphere(sphere, p));
}

Location point_in_halfspace(const Plane& plane, Vec3 p) {
  return from_sign(predicates::side_of_plane(plane, p));
}

Location point_in_box(const Box3& box, Vec3 p) {
  // A closed box is the intersection of three closed slabs: outside if outside one, boundary if
  // on the boundary of one and inside the others.
  const Location axes[3] = {in_interval(p.x, box.min.x, box.max.x),
                            in_interval(p.y, box.min.y, box.max.y),
                            in_interval(p.z, box.min.z, box.max.z)};
  Location result = Location::inside;
  for (Location l : axes) {
    if (l == Location::outside) return Location::outside;
    if (l == Location::boundary) result = Location::boundary;
  }
  return result;
}

Location point_in_implicit(const ImplicitFunction& f, Vec3 p) {
  const double value = f(p);
  if (value > 0) return Location::inside;
  if (value == 0) return Location::boundary;
  return Location::outside;  // negative or NaN
}

}  // namespace contain::inside
