#include "inside/mesh_ray.h"

#include <algorithm>

#include "contain/inside/point_in_triangle.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/values/box.h"

namespace contain::inside::detail {
namespace {

// Gradients in q of the tests of the perturbed ray: orient2d_yz(a, b, q) and orient3d(a, b, c, q).
BigVec3 gradient_yz(Vec3 a, Vec3 b) {
  return {BigFloat(), BigFloat(a.z) - BigFloat(b.z), BigFloat(b.y) - BigFloat(a.y)};
}
BigVec3 gradient_normal(Vec3 a, Vec3 b, Vec3 c) {
  const BigVec3 ea = to_big(a);
  return cross(to_big(b) - ea, to_big(c) - ea);
}

// The sample's offset from p, as predicates/perturbed_ray.h asks of a symbolic origin: the sign
// of g . (q - p) for the sample q and the test's gradient g, read term by term (sign_at).
struct SampleOffset {
  static constexpr bool symbolic = true;
  const SymbolicOffset* at;
  [[nodiscard]] Sign along_yz(Vec3 a, Vec3 b) const {
    return sign_at(BigFloat(), gradient_yz(a, b), *at);
  }
  [[nodiscard]] Sign along_normal(Vec3 a, Vec3 b, Vec3 c) const {
    return sign_at(BigFloat(), gradient_normal(a, b, c), *at);
  }
};

Sign compare(double u, double v) {
  return u > v ? Sign::positive : (u < v ? Sign::negative : Sign::zero);
}

// The same for a LocalSample. The tests vanish at p when asked, so along the direction to an
// input point v a test's sign is its value at v; along an axis, the sign of that component of
// its gradient, a comparison or a 2D orientation of input coordinates; only exact vectors (the
// rare crossings of two faces through p) need exact arithmetic.
struct LocalOffset {
  static constexpr bool symbolic = true;
  const LocalSample* at;

  template <class AtPoint, class AlongAxis, class Gradient>
  [[nodiscard]] Sign first_sign(const AtPoint& at_point, const AlongAxis& along_axis,
                                const Gradient& gradient) const {
    for (std::size_t i = 0; i < at->count; ++i) {
      const LocalTerm& t = at->terms[i];
      Sign s = Sign::zero;
      if (t.kind == LocalTerm::Kind::point) {
        s = at_point(t.point);
      } else if (t.kind == LocalTerm::Kind::axis) {
        s = t.sign > 0 ? along_axis(t.axis) : -along_axis(t.axis);
      } else {
        s = dot(gradient(), *t.vector).sign();
      }
      if (s != Sign::zero) return s;
    }
    return Sign::zero;
  }

  [[nodiscard]] Sign along_yz(Vec3 a, Vec3 b) const {
    return first_sign(
        [&](Vec3 v) {
          return predicates::orient2d({a.y, a.z}, {b.y, b.z}, {v.y, v.z});
        },
        [&](int axis) {
          return axis == 0 ? Sign::zero : (axis == 1 ? compare(a.z, b.z) : compare(b.y, a.y));
        },
        [&] { return gradient_yz(a, b); });
  }
  [[nodiscard]] Sign along_normal(Vec3 a, Vec3 b, Vec3 c) const {
    return first_sign([&](Vec3 v) { return predicates::orient3d(a, b, c, v); },
                      [&](int axis) {
                        // The components of (b - a) x (c - a): 2D orientations of projections.
                        if (axis == 0)
                          return predicates::orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z});
                        if (axis == 1)
                          return predicates::orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x});
                        return predicates::orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y});
                      },
                      [&] { return gradient_normal(a, b, c); });
  }
};

}  // namespace

void MeshRay::add(Vec3 a, Vec3 b, Vec3 c) {
  // Triangles that the ray from a point near p cannot reach (exact comparisons of inputs).
  if (std::max({a.x, b.x, c.x}) < p_.x || std::min({a.y, b.y, c.y}) > p_.y ||
      std::max({a.y, b.y, c.y}) < p_.y || std::min({a.z, b.z, c.z}) > p_.z ||
      std::max({a.z, b.z, c.z}) < p_.z) {
    return;
  }
  const Sign s = predicates::projected_sign(a, b, c);
  if (s == Sign::zero) return;  // never crossed by an x ray
  // The rule's four tests at p, each of which must equal s for a crossing: the three edges of the
  // (y, z) projection, and the plane met ahead (-orient3d, see hit_side).
  const Vec2 pa{a.y, a.z}, pb{b.y, b.z}, pc{c.y, c.z}, pp{p_.y, p_.z};
  const Sign at_p[4] = {predicates::orient2d(pa, pb, pp), predicates::orient2d(pb, pc, pp),
                        predicates::orient2d(pc, pa, pp), -predicates::orient3d(a, b, c, p_)};
  if (std::any_of(at_p, at_p + 4, [&](Sign e) { return e != Sign::zero && e != s; })) return;
  if (std::none_of(at_p, at_p + 4, [](Sign e) { return e == Sign::zero; })) {
    decided_ += to_int(s);
  } else {
    open_.emplace_back(Triangle3{a, b, c}, to_int(s));
  }
}

template <class Offset>
int MeshRay::count_from(const Offset& offset) const {
  int count = decided_;
  for (const auto& [t, s] : open_) {
    if (predicates::perturbed_ray_crosses(t.a, t.b, t.c, p_, offset)) count += s;
  }
  return count;
}

int MeshRay::winding(const SymbolicOffset& at) const {
  return count_from(SampleOffset{&at});
}

int MeshRay::winding(const LocalSample& at) const {
  return count_from(LocalOffset{&at});
}

bool face_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p) {
  const Triangle3 tri{a, b, c};
  return bounding_box(tri).contains(p) && predicates::orient3d(a, b, c, p) == Sign::zero &&
         !predicates::collinear(a, b, c) && point_in_triangle(tri, p) != Location::outside;
}

void add_plane_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p, std::vector<LocalConstraint>& out) {
  if (!face_through(a, b, c, p)) return;
  const BigVec3 ea = to_big(a);
  out.push_back({cross(to_big(b) - ea, to_big(c) - ea), false, false});
}

}  // namespace contain::inside::detail
