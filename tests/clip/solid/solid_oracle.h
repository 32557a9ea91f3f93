#pragma once
// The GMP oracle and the generators of the mesh boolean tests: exact winding numbers at sample
// points, exact volumes, and solids (boxes, tetrahedra, icospheres) built from doubles.

#include <gmpxx.h>

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/shapes/mesh.h"

namespace contain::test {

/// The winding number of `mesh` at p, counted exactly along the +x ray; nullopt when p lies on
/// the mesh or the ray meets an edge or a vertex (the caller takes another sample).
[[nodiscard]] std::optional<int> exact_winding(const Mesh& mesh, Vec3 p);

/// Why `mesh` is not a valid written solid ("" when it is): every directed edge matched by
/// exactly one opposite, no zero-area triangle (exact), no two triangles meeting other than at
/// shared corners (collide::self_intersections), and its winding number 0 or 1: each shell
/// outward with the others' winding number 0 around it, or inward with 1 (exact volumes and
/// winding numbers at the shells' vertices).
[[nodiscard]] std::string invalid_reason(const Mesh& mesh);

/// Whether a point with these winding numbers of the inputs is in the result of `op`.
[[nodiscard]] bool in_result(clip::Op op, std::span<const int> windings);

/// The closed box [lo, hi], outward.
[[nodiscard]] Mesh box_mesh(Vec3 lo, Vec3 hi);
/// The tetrahedron a b c d, outward whatever the order given.
[[nodiscard]] Mesh tetrahedron(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
/// An icosphere: the icosahedron subdivided `levels` times, 20 * 4^levels triangles, outward.
[[nodiscard]] Mesh icosphere(int levels, double radius, Vec3 center);
/// Every triangle reversed (an inside-out shell).
[[nodiscard]] Mesh reversed(Mesh mesh);
/// The meshes' vertices and triangles in one mesh.
[[nodiscard]] Mesh joined(const Mesh& a, const Mesh& b);

/// The triangles as given as a soup of one input: no welding and no closedness check (the open,
/// folded and degenerate patches and stars the proofs must refuse); zero-area triangles marked
/// degenerate with empty boxes, as make_soup marks them.
[[nodiscard]] clip::solid::Soup raw_soup(const std::vector<Vec3>& vertices,
                                         const std::vector<TriangleIndices>& triangles);

}  // namespace contain::test
