#pragma once
// Private to contain::inside: the perturbed +x ray of a mesh from symbolic samples near a point p
// on its surface, counted with signs (the winding number), and the planes of the triangles
// through p; the neighbourhood analysis of MeshIndex and of CsgSolid's mesh leaves at p
// (csg_local.h samples the open cells around p).

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
/// if none is, else `boundary`.
template <class InsideAt>
[[nodiscard]] Location classify_surface_point(const std::vector<LocalConstraint>& planes,
                                              const MeshRay& ray, const InsideAt& inside_at) {
  return classify_neighbourhood(planes, [&](std::span<const char>, const SymbolicOffset& at) {
    return inside_at(ray.winding(at));
  });
}

}  // namespace contain::inside::detail
