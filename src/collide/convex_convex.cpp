#include "contain/collide/convex_convex.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contain/bound/gjk.h"
#include "contain/collide/tri_tri.h"
#include "contain/inside/point_in_convex.h"
#include "contain/predicates/side_of_plane.h"
#include "contain/values/plane.h"

namespace contain::collide {

namespace {

// Distances below this fraction of the shapes' size are not trusted to separate them.
constexpr double kMargin = 1e-12;

// GJK on a - b (bound::gjk): v = a - b at its closest.
bound::GjkResult gjk(const ConvexShape& a, const ConvexShape& b) {
  return bound::gjk([&](Vec3 d) { return a.support(d); }, [&](Vec3 d) { return b.support(d); });
}

// ---- exact stage for polytopes -------------------------------------------------------------

// A plane with normal n strictly between the two vertex sets, checked exactly: all of a's
// vertices strictly on its positive side, all of b's strictly on its negative side.
bool certified_separation(const ConvexPolyhedron& a, const ConvexPolyhedron& b, Vec3 n) {
  const std::vector<Vec3>& va = a.vertices();
  const std::vector<Vec3>& vb = b.vertices();
  double lo_a = INFINITY, hi_b = -INFINITY;
  for (const Vec3& p : va)
    lo_a = std::min(lo_a, dot(n, p));
  for (const Vec3& p : vb)
    hi_b = std::max(hi_b, dot(n, p));
  const double t = 0.5 * lo_a + 0.5 * hi_b;
  if (!std::isfinite(t)) return false;
  const Plane plane{n.x, n.y, n.z, -t};
  for (const Vec3& p : va)
    if (predicates::side_of_plane(plane, p) != Sign::positive) return false;
  for (const Vec3& p : vb)
    if (predicates::side_of_plane(plane, p) != Sign::negative) return false;
  return true;
}

// Closed convex solids meet iff their surfaces meet or one holds a vertex of the other (if the
// surfaces are apart, each surface is wholly inside or wholly outside the other solid).
bool polytopes_meet(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const auto faces_a = static_cast<std::int32_t>(a.face_indices().size());
  const auto faces_b = static_cast<std::int32_t>(b.face_indices().size());
  for (std::int32_t i = 0; i < faces_a; ++i) {
    const Triangle3 fa = a.face(i);
    for (std::int32_t j = 0; j < faces_b; ++j)
      if (tri_tri(fa, b.face(j))) return true;
  }
  return inside::point_in_convex(b, a.vertices()[0]) != Location::outside ||
         inside::point_in_convex(a, b.vertices()[0]) != Location::outside;
}

}  // namespace

ConvexShape ConvexShape::sphere(const Sphere& sphere) {
  ConvexShape s;
  s.sphere_ = sphere;
  return s;
}

ConvexShape ConvexShape::box(const Box3& box) {
  ConvexShape s;
  s.solid_ = ConvexPolyhedron::from_box(box);
  return s;
}

Result<ConvexShape> ConvexShape::polyhedron(const ConvexPolyhedron& polyhedron) {
  if (polyhedron.vertices().empty()) {
    return Error{ErrorKind::unsupported,
                 "a convex polyhedron given by planes has no vertices: build it from a mesh"};
  }
  ConvexShape s;
  s.solid_ = polyhedron;
  return s;
}

Vec3 ConvexShape::support(Vec3 direction) const {
  if (solid_.vertices().empty()) {
    const double len = length(direction);
    if (!(len > 0)) return sphere_.center;
    return sphere_.center + (sphere_.radius / len) * direction;
  }
  return solid_.support(direction);
}

ConvexContact convex_convex(const ConvexShape& a, const ConvexShape& b) {
  const bool polytopes = a.is_polytope() && b.is_polytope();
  const bound::GjkResult r = gjk(a, b);
  const double distance = r.origin_inside ? 0.0 : length(r.v);
  if (polytopes) {
    // v = a - b at its closest: a lies on the side v points to.
    if (!r.origin_inside && r.lower > 0 && certified_separation(a.polytope(), b.polytope(), r.v)) {
      return {false, distance, true};
    }
    const bool meet = polytopes_meet(a.polytope(), b.polytope());
    return {meet, meet ? 0.0 : distance, true};
  }
  const bool separated = !r.origin_inside && r.lower > kMargin * r.size;
  return {!separated, separated ? distance : 0.0, false};
}

}  // namespace contain::collide
