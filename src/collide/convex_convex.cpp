#include "contain/collide/convex_convex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "contain/bound/gjk.h"
#include "contain/collide/tri_tri.h"
#include "contain/inside/point_in_convex.h"
#include "contain/predicates/side_of_plane.h"
#include "contain/values/plane.h"

namespace contain::collide {

// Builds shapes and reads their private parts for the query below.
struct ConvexAccess {
  static ConvexShape make() { return ConvexShape(); }
  static Sphere& sphere(ConvexShape& s) { return s.sphere_; }
  static std::vector<Vec3>& vertices(ConvexShape& s) { return s.vertices_; }
  static std::vector<Triangle3>& faces(ConvexShape& s) { return s.faces_; }
  static ConvexPolyhedron& solid(ConvexShape& s) { return s.solid_; }
  static const std::vector<Vec3>& vertices(const ConvexShape& s) { return s.vertices_; }
  static const std::vector<Triangle3>& faces(const ConvexShape& s) { return s.faces_; }
  static const ConvexPolyhedron& solid(const ConvexShape& s) { return s.solid_; }
};

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
bool certified_separation(const ConvexShape& a, const ConvexShape& b, Vec3 n) {
  const auto& va = ConvexAccess::vertices(a);
  const auto& vb = ConvexAccess::vertices(b);
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
bool polytopes_meet(const ConvexShape& a, const ConvexShape& b) {
  for (const Triangle3& fa : ConvexAccess::faces(a))
    for (const Triangle3& fb : ConvexAccess::faces(b))
      if (tri_tri_intersect(fa, fb)) return true;
  return inside::point_in_convex(ConvexAccess::solid(b), ConvexAccess::vertices(a)[0]) !=
             Location::outside ||
         inside::point_in_convex(ConvexAccess::solid(a), ConvexAccess::vertices(b)[0]) !=
             Location::outside;
}

}  // namespace

ConvexShape ConvexShape::sphere(const Sphere& sphere) {
  ConvexShape s;
  s.sphere_ = sphere;
  return s;
}

ConvexShape ConvexShape::box(const Box3& box) {
  ConvexShape s;
  Vec3 c[8];
  for (int i = 0; i < 8; ++i) {
    c[i] = {(i & 1) != 0 ? box.max.x : box.min.x, (i & 2) != 0 ? box.max.y : box.min.y,
            (i & 4) != 0 ? box.max.z : box.min.z};
  }
  s.vertices_.assign(c, c + 8);
  // Two triangles per side (corner indices by bits x = 1, y = 2, z = 4), outward.
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads) {
    s.faces_.push_back({c[q[0]], c[q[1]], c[q[2]]});
    s.faces_.push_back({c[q[0]], c[q[2]], c[q[3]]});
  }
  // Inward half-spaces x - min.x >= 0, max.x - x >= 0, ...: exact coefficients.
  auto solid = ConvexPolyhedron::from_planes(
      {Plane{1, 0, 0, -box.min.x}, Plane{-1, 0, 0, box.max.x}, Plane{0, 1, 0, -box.min.y},
       Plane{0, -1, 0, box.max.y}, Plane{0, 0, 1, -box.min.z}, Plane{0, 0, -1, box.max.z}});
  if (solid) s.solid_ = std::move(*solid);
  return s;
}

Result<ConvexShape> ConvexShape::polyhedron(const ConvexPolyhedron& polyhedron) {
  if (polyhedron.faces().empty()) {
    return Error{ErrorKind::unsupported,
                 "a convex polyhedron given by planes has no vertices: build it from a mesh"};
  }
  ConvexShape s;
  s.faces_ = polyhedron.faces();
  for (const Triangle3& t : s.faces_) {
    s.vertices_.push_back(t.a);
    s.vertices_.push_back(t.b);
    s.vertices_.push_back(t.c);
  }
  const auto less = [](Vec3 p, Vec3 q) {
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  };
  std::sort(s.vertices_.begin(), s.vertices_.end(), less);
  s.vertices_.erase(std::unique(s.vertices_.begin(), s.vertices_.end()), s.vertices_.end());
  s.solid_ = polyhedron;
  return s;
}

Vec3 ConvexShape::support(Vec3 direction) const {
  if (vertices_.empty()) {
    const double len = length(direction);
    if (!(len > 0)) return sphere_.center;
    return sphere_.center + (sphere_.radius / len) * direction;
  }
  Vec3 best = vertices_[0];
  double best_dot = dot(direction, best);
  for (const Vec3& p : vertices_) {
    const double d = dot(direction, p);
    if (d > best_dot) {
      best_dot = d;
      best = p;
    }
  }
  return best;
}

ConvexContact convex_intersect(const ConvexShape& a, const ConvexShape& b) {
  const bool polytopes = a.is_polytope() && b.is_polytope();
  const bound::GjkResult r = gjk(a, b);
  const double distance = r.origin_inside ? 0.0 : length(r.v);
  if (polytopes) {
    // v = a - b at its closest: a lies on the side v points to.
    if (!r.origin_inside && r.lower > 0 && certified_separation(a, b, r.v)) {
      return {false, distance, true};
    }
    const bool meet = polytopes_meet(a, b);
    return {meet, meet ? 0.0 : distance, true};
  }
  const bool separated = !r.origin_inside && r.lower > kMargin * r.size;
  return {!separated, separated ? distance : 0.0, false};
}

}  // namespace contain::collide
