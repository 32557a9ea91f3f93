#pragma once
/// \file
/// The answer of a solid or surface collision query, with its witness.

#include <cstddef>
#include <cstdint>

#include "contain/inside/pair_witness.h"

namespace contain::collide {

/// The words of a collision's witness (`inside::PairWitness`: what proves that two shapes
/// intersect, `none`: disjoint), the enumerators' names: "none", "triangles", "edges",
/// "vertex_of_a_in_b", "vertex_of_b_in_a".
[[nodiscard]] constexpr const char* to_string(inside::PairWitness kind) {
  switch (kind) {
    case inside::PairWitness::triangles:
      return "triangles";
    case inside::PairWitness::edges:
      return "edges";
    case inside::PairWitness::vertex_of_a_in_b:
      return "vertex_of_a_in_b";
    case inside::PairWitness::vertex_of_b_in_a:
      return "vertex_of_b_in_a";
    case inside::PairWitness::none:
      break;
  }
  return "none";
}

/// Result of a collision query: `intersect` and one witness where they intersect, plus counts
/// of the work done (for benchmarks and `--json`).
struct Contact {
  bool intersect = false;
  inside::PairWitness witness = inside::PairWitness::none;
  std::int32_t triangle_a = -1;  ///< inside::PairWitness::triangles: a triangle (or edge/face) of A
  std::int32_t triangle_b = -1;  ///< inside::PairWitness::triangles: a triangle of B
  std::int32_t vertex = -1;      ///< vertex witnesses: the vertex index in its own mesh
  std::size_t node_pairs = 0;    ///< bounding volume pairs tested
  std::size_t exact_tests = 0;   ///< exact primitive tests run
};

}  // namespace contain::collide
