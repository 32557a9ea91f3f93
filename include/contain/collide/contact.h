#pragma once
/// \file
/// The answer of a solid or surface collision query, with its witness.

#include <cstddef>
#include <cstdint>

namespace contain::collide {

/// What proves that two shapes intersect.
enum class WitnessKind : std::uint8_t {
  none,              ///< disjoint (no witness)
  triangles,         ///< triangle_a and triangle_b share a point
  edges,             ///< 2D: edge triangle_a of A and edge triangle_b of B share a point
  vertex_of_a_in_b,  ///< vertex `vertex` of A lies in the solid B (nested, no surface contact)
  vertex_of_b_in_a,  ///< vertex `vertex` of B lies in the solid A
};

/// "none", "triangles", "edges", "vertex_of_a_in_b", "vertex_of_b_in_a".
[[nodiscard]] constexpr const char* to_string(WitnessKind kind) {
  switch (kind) {
    case WitnessKind::triangles:
      return "triangles";
    case WitnessKind::edges:
      return "edges";
    case WitnessKind::vertex_of_a_in_b:
      return "vertex_of_a_in_b";
    case WitnessKind::vertex_of_b_in_a:
      return "vertex_of_b_in_a";
    case WitnessKind::none:
      break;
  }
  return "none";
}

/// Result of a collision query: `intersect` and one witness where they intersect, plus counts
/// of the work done (for benchmarks and `--json`).
struct Contact {
  bool intersect = false;
  WitnessKind witness = WitnessKind::none;
  std::int32_t triangle_a = -1;  ///< WitnessKind::triangles: a triangle (or edge/face) of A
  std::int32_t triangle_b = -1;  ///< WitnessKind::triangles: a triangle of B
  std::int32_t vertex = -1;      ///< vertex witnesses: the vertex index in its own mesh
  std::size_t node_pairs = 0;    ///< bounding volume pairs tested
  std::size_t exact_tests = 0;   ///< exact primitive tests run
};

}  // namespace contain::collide
