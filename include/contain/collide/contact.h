#pragma once
/// \file
/// The answer of a solid or surface collision query, with its witness.

#include <cstddef>
#include <cstdint>

#include "contain/inside/pair_witness.h"

namespace contain::collide {

/// What proves that two shapes intersect (`none`: disjoint); the pair witness that distance's
/// `PairContact` also names.
using WitnessKind = inside::PairWitness;

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
