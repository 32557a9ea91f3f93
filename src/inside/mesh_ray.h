#pragma once
// Private to contain::inside: the perturbed +x ray of a mesh from symbolic samples near a point p
// on its surface, counted with signs (the winding number), and the planes of the triangles
// through p; the neighbourhood analysis of MeshIndex and of CsgSolid's mesh leaves at p
// (csg_local.h samples the open cells around p).

#include <algorithm>
#include <utility>
#include <vector>

#include "contain/core/location.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "inside/csg_local.h"

namespace contain::inside::detail {

/// The crossings of the perturbed +x ray (predicates/perturbed_ray.h) from a symbolic sample q
/// near p, q's offset from p ordered before the ray's own perturbation (0, e, e²), each counted
/// with the sign of its triangle's normal along x: on a mesh whose directed edges all match, the
/// winding number of q (its parity, the crossing parity, on any closed mesh). Crossings decided
/// at p itself (every test non-zero there) are the same for every sample and counted once; the
/// few triangles with a test that vanishes at p are kept and tested per sample.
class MeshRay {
 public:
  MeshRay() = default;
  explicit MeshRay(Vec3 p) : p_(p) {}

  /// Counts a triangle of the mesh (any order; a triangle the ray from a sample near p cannot
  /// reach is skipped by exact comparisons).
  void add(Vec3 a, Vec3 b, Vec3 c);

  /// The signed count of crossings of the ray from the sample `at`.
  [[nodiscard]] int winding(const SymbolicOffset& at) const;

 private:
  Vec3 p_;
  int decided_ = 0;                              // crossings decided at p itself, signed
  std::vector<std::pair<Triangle3, int>> open_;  // triangles with a test that vanishes at p, sign
};

/// Appends the plane of triangle (a, b, c) when the closed triangle contains p and has a
/// non-zero area: near p such planes carry the whole surface, so every open cell of their
/// arrangement is inside or outside.
void add_plane_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p, std::vector<LocalConstraint>& out);

/// Where the surface point p lies in the solid whose inside is where `inside_at(count)` holds for
/// the signed crossing count of `ray`: `inside` if every open cell around p is inside, `outside`
/// if none is, else `boundary`. `planes`: those of the triangles through p (add_plane_through);
/// `face`: one of those triangles.
///
/// First a quick proof of the common answer: two samples just on either side of `face`, in its
/// wedge at p (p + e d +- e^2 n + e^2 d1 x + e^2 d2 y, d from p to the face's centroid, n its
/// normal). Where both lie off every plane through p (so off the surface) and one is inside and
/// the other not, p is `boundary`, without the arrangement, whose sampling grows with the cube
/// of the number of planes through p (a vertex of high degree).
template <class InsideAt>
[[nodiscard]] Location classify_surface_point(const std::vector<LocalConstraint>& planes,
                                              const Triangle3& face, Vec3 p, const MeshRay& ray,
                                              const InsideAt& inside_at) {
  if (!planes.empty()) {
    const BigVec3 d =
        to_big(face.a) + to_big(face.b) + to_big(face.c) - to_big(p) - to_big(p) - to_big(p);
    const BigVec3 n = cross(to_big(face.b) - to_big(face.a), to_big(face.c) - to_big(face.a));
    const BigVec3 back = -n, x = to_big(Vec3{1, 0, 0}), y = to_big(Vec3{0.375, 1, 0.625});
    const SymbolicOffset ahead{&d, &n, &x, &y}, behind{&d, &back, &x, &y};
    const auto off_surface = [&](const SymbolicOffset& at) {
      return std::none_of(planes.begin(), planes.end(), [&](const LocalConstraint& c) {
        return sign_at(BigFloat(), c.normal, at) == Sign::zero;
      });
    };
    if (off_surface(ahead) && off_surface(behind) &&
        inside_at(ray.winding(ahead)) != inside_at(ray.winding(behind))) {
      return Location::boundary;
    }
  }
  return classify_neighbourhood(planes, [&](std::span<const char>, const SymbolicOffset& at) {
    return inside_at(ray.winding(at));
  });
}

}  // namespace contain::inside::detail
