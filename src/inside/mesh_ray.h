#pragma once
// Private to contain::inside: the perturbed +x ray of a mesh from symbolic samples near a point p
// on its surface, counted with signs (the winding number), and the triangles through p; the
// neighbourhood analysis of MeshIndex (surface_star.h) and of CsgSolid's mesh leaves at p
// (csg_local.h samples the open cells around p).

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "contain/core/location.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "inside/csg_local.h"

namespace contain::inside::detail {

/// One term of a sample's offset from p, in the order of csg_local.h's SymbolicOffset (each term
/// infinitely smaller than the one before): the direction from p to an input point, a signed
/// axis, or an exact vector. Along an input point v an affine test F that vanishes at p has the
/// sign of F(v), a predicate on the given doubles: no exact arithmetic unless the filter fails.
struct LocalTerm {
  enum class Kind : std::uint8_t { point, axis, vector };
  Kind kind = Kind::point;
  Vec3 point;                       ///< kind point: the direction point - p
  int axis = 0;                     ///< kind axis: sign * e_axis
  int sign = 1;                     ///< kind axis: +1 or -1
  const BigVec3* vector = nullptr;  ///< kind vector (not owned)
};

/// The sample p + e1 t1 + e2 t2 + e3 t3, 0 < e3 << e2 << e1 << 1, of `count` terms (none: p).
struct LocalSample {
  std::array<LocalTerm, 3> terms;
  std::size_t count = 0;
};

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
  /// The same from a sample of input points and axes (surface_star.h).
  [[nodiscard]] int winding(const LocalSample& at) const;

 private:
  template <class Offset>
  [[nodiscard]] int count_from(const Offset& offset) const;

  Vec3 p_;
  int decided_ = 0;                              // crossings decided at p itself, signed
  std::vector<std::pair<Triangle3, int>> open_;  // triangles with a test that vanishes at p, sign
};

/// Whether the closed triangle (a, b, c) contains p and has a non-zero area: near p such
/// triangles carry the whole surface.
[[nodiscard]] bool face_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p);

/// Appends the plane of triangle (a, b, c) when face_through(a, b, c, p): every open cell of the
/// arrangement of such planes is inside or outside.
void add_plane_through(Vec3 a, Vec3 b, Vec3 c, Vec3 p, std::vector<LocalConstraint>& out);

}  // namespace contain::inside::detail
