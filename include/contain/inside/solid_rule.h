#pragma once
/// \file
/// How the signed crossing count of the perturbed +x ray reads as inside a closed mesh: the one
/// rule of `MeshIndex` (its regime), of the CSG mesh leaves and of the pair queries' nesting test
/// (`locate_by_ray`, placed_ray.h), so that `inside`, `collide` and the mesh-pair distance read a
/// mesh as the same solid.

#include <cstdint>

#include "contain/shapes/mesh.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::inside {

/// What a mesh's signed crossing count (each crossing of the perturbed +x ray counted +1 where
/// the triangle's normal points along +x, -1 where against) means.
enum class SolidRule : std::uint8_t {
  /// Not closed (a border edge, an unmatched non-manifold edge, no triangles): no solid; the
  /// count means nothing (MeshIndex answers by the generalized winding number instead).
  none,
  /// Every directed edge as often as its reverse (by position): the count is the winding number
  /// and the solid is where it is positive (**solid's rule**: overlapping parts count once, a
  /// shell turned inside out subtracts).
  winding,
  /// Every edge of exactly two triangles but directed edges unmatched (inconsistent orientation):
  /// no winding number; the solid is where the count is odd (ray parity).
  parity,
};

/// The rule of `mesh`, whose validation is `report` (validate_mesh(mesh)): `winding` where every
/// directed edge is matched, else `parity` where the report is closed, else `none`. O(1) for a
/// closed, consistently oriented mesh; else O(n log n) (shapes::unmatched_edge).
[[nodiscard]] SolidRule solid_rule(const Mesh& mesh, const MeshReport& report);

/// Is a point whose signed crossing count is `count` inside the solid of `rule`? `none`: never.
[[nodiscard]] constexpr bool inside_by_count(SolidRule rule, int count) {
  switch (rule) {
    case SolidRule::winding:
      return count > 0;
    case SolidRule::parity:
      return (count & 1) != 0;
    case SolidRule::none:
      break;
  }
  return false;
}

}  // namespace contain::inside
