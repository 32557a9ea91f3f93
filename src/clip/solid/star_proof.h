#pragma once
// Neighbour pairs of the pair stage settled per vertex instead of per pair: most
// candidate pairs of a soup's triangles are neighbours in one mesh that share a corner or an
// edge and meet nowhere else (1.61 M of the 1.63 M pairs of a union of two 131k-triangle
// spheres), each of which `intersect_pair` would settle by its own tests.
//
// A vertex v is proven when the soup's triangles around it (every triangle with v as a corner,
// of every input) form one closed fan v w0 w1, v w1 w2, ..., v w(n-1) w0 (the ring's vertices
// distinct, n >= 3) such that, exactly, in the projection dropping one coordinate axis:
//   1. every triangle v wi w(i+1) turns the same strict way (orient2d all > 0 or all < 0), and
//   2. the ring winds once around v (the direction of w0 lies in exactly one of the half-open
//      sectors (wi, w(i+1)]),
// and in space
//   3. every turn of the ring turns the same strict way: orient3d(v, wi, w(i+1), w(i+2)) all > 0
//      or all < 0.
// Why that suffices. By 1 and 2 the projected sectors (the angles between wi and w(i+1), each
// below pi) tile the plane around v once, so the fan is the graph of a continuous function h over
// the plane, linear (Li) on each sector. By 3, h bends the same strict way across every ray
// (w(i+2) strictly above the plane of v wi w(i+1) means L(i+1) > Li beyond the ray of w(i+1)), so
// h is strictly convex across each ray (or concave): a locally convex function on the plane is
// convex, h >= Li everywhere, and h > Li off the closed sector i (where h = Li on a larger convex
// set, it would equal Li inside a neighbouring sector). So every ring vertex but wi and w(i+1)
// lies strictly on one side of the plane of v wi w(i+1). Then in `intersect_pair`:
//   - two triangles of the fan sharing only v have the other's two other corners strictly on one
//     side of their plane: `one_side` settles them, no constraint, no coplanar partner;
//   - two sharing the edge v w(i+1) are not coplanar (w(i+2) is off the plane): no fold.
// A pair of triangles that share a proven vertex gives nothing, and is skipped before its test.
// A star with a zero-area or repeated triangle, an open or non-manifold star, a vertex of two
// inputs' cones, a saddle, a flat fan and a ring winding twice are not proven (tested by
// star_proof_test against the pair test itself).

#include <array>
#include <cstdint>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::clip::solid {

/// Whether each vertex of the soup is proven (see above).
[[nodiscard]] std::vector<bool> proven_vertices(const Soup& soup);

/// For each triangle of the soup: bit k set when its corner k is a proven vertex.
[[nodiscard]] std::vector<std::uint8_t> proven_corners(const Soup& soup);

/// `proven_corners`, and each triangle's neighbour across each of its edges that has a proven
/// end (-1 for the others): across[t][k] is the triangle on the other side of the edge from
/// corner k to corner k + 1 (mod 3), which runs the other way there (a proven star is a closed
/// fan, so an edge at a proven vertex has exactly two triangles).
struct ProvenStars {
  std::vector<std::uint8_t> corners;
  std::vector<std::array<std::int32_t, 3>> across;
};
[[nodiscard]] ProvenStars proven_stars(const Soup& soup);

/// Whether `intersect_pair` would give triangles t and u (t < u) a constraint or a coplanar
/// partner, or make a crossing point on the way (for the tests; defined in intersect.cpp).
[[nodiscard]] bool pair_gives_work(const Soup& soup, std::int32_t t, std::int32_t u);

}  // namespace contain::clip::solid
