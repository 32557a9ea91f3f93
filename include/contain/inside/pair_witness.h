#pragma once
/// \file
/// What proves how two shapes of a pair relate: the one witness type of collide's answers
/// (`collide::Contact::witness`) and distance's (`distance::PairDistance3::contact`).

#include <cstdint>

namespace contain::inside {

/// The witness of a pair query's answer. Collision: what proves that the shapes intersect
/// (`none`: disjoint). Distance: how the shapes relate at the answer (`none`: distance > 0; any
/// other: distance 0). The words printed for each use stay with that use
/// (`collide::to_string`, `distance::to_string`).
enum class PairWitness : std::uint8_t {
  none,              ///< disjoint, distance > 0 (no witness)
  triangles,         ///< triangle (or face) `triangle_a` of A and `triangle_b` of B share a point
  edges,             ///< 2D: edge `triangle_a` of A and edge `triangle_b` of B share a point
  vertex_of_a_in_b,  ///< vertex `vertex` of A lies in the solid B (overlap or nesting)
  vertex_of_b_in_a,  ///< vertex `vertex` of B lies in the solid A (overlap or nesting)
};

}  // namespace contain::inside
