#pragma once
/// \file
/// The generalized winding number of a mesh at many points: a BVH over the triangles with a
/// far-field dipole approximation per node (after Barill, Dickson, Schmidt, Levin and Jacobson,
/// "Fast Winding Numbers for Soups and Clouds", SIGGRAPH 2018, first order).

#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/shapes/mesh.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// How a `FastWindingNumber` trades accuracy for speed.
struct FastWindingNumberOptions {
  /// A node is treated as one dipole when the point is farther than `accuracy` times the
  /// node's radius from the node's area-weighted centre. Larger: more accurate, slower.
  double accuracy = 3.0;
};

/// A mesh prepared for generalized winding numbers (see winding_number_3d.h). Near the point
/// every triangle counts exactly (solid angles); far nodes count as one dipole (the sum of their
/// area vectors at their area-weighted centre), whose relative error falls like
/// (radius / distance)^2. Floating point, deterministic (a fixed traversal order).
/// Build O(n log n); a query about O(log n) for points away from the surface.
/// Thread safety: const queries may run concurrently.
class FastWindingNumber {
 public:
  FastWindingNumber() = default;
  /// Prepares `mesh` (validated: indices in range).
  explicit FastWindingNumber(const Mesh& mesh, const FastWindingNumberOptions& options = {});

  /// The generalized winding number at p (approximately `generalized_winding_number(mesh, p)`).
  [[nodiscard]] double evaluate(Vec3 p) const;

  /// The hierarchy over the triangles (item t is triangle t), for exact tests on the surface.
  [[nodiscard]] const bvh::Bvh& hierarchy() const { return bvh_; }
  /// The accuracy it was built with (`FastWindingNumberOptions::accuracy`).
  [[nodiscard]] double accuracy() const { return accuracy_; }
  /// The triangles, in the mesh's order.
  [[nodiscard]] std::span<const Triangle3> triangles() const { return triangles_; }

 private:
  struct Dipole {
    Vec3 centre;       // area-weighted centroid
    Vec3 area_vector;  // sum of (b - a) x (c - a) / 2
    double radius2;    // (accuracy * radius)^2
  };
  std::vector<Triangle3> triangles_;
  bvh::Bvh bvh_;
  std::vector<Dipole> dipoles_;  // per node
  double accuracy_ = FastWindingNumberOptions{}.accuracy;
};

}  // namespace contain::inside
