#include "inside/mesh_ray.h"

#include <algorithm>

#include "contain/inside/point_in_triangle.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/values/box.h"

namespace contain::inside::detail {
namespace {

// The sample's offset from p, as predicates/perturbed_ray.h asks of a symbolic origin: the sign
// of g . (q - p) for the sample q, read term by term (sign_at).
struct SampleOffset {
  static constexpr bool symbolic = true;
  const SymbolicOffset* at;
  [[nodiscard]] Sign along(const BigVec3& g) const { return sign_at(BigFloat(), g, *at); }
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

int MeshRay::winding(const SymbolicOffset& at) const {
  int count = decided_;
  const SampleOffset offset{&at};
  for (const auto& [t, s] : open_) {
    if (predicates::perturbed_ray_crosses(t.a, t.b, t.c, p_, offset)) count += s;
  }
  return count;
}

void add_plane_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p, std::vector<LocalConstraint>& out) {
  const Triangle3 tri{a, b, c};
  if (!bounding_box(tri).contains(p) || predicates::orient3d(a, b, c, p) != Sign::zero ||
      point_in_triangle(tri, p) == Location::outside) {
    return;
  }
  const BigVec3 ea = to_big(a);
  BigVec3 normal = cross(to_big(b) - ea, to_big(c) - ea);
  if (!is_zero(normal)) out.push_back({std::move(normal), false, false});
}

}  // namespace contain::inside::detail
