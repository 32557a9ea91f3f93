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
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/predicates/unit_roundoff.h"

namespace contain::clip::solid {

/// Whether each vertex of the soup is proven (see above).
[[nodiscard]] std::vector<bool> proven_vertices(const Soup& soup);

/// For each triangle of the soup: bit k set when its corner k is a proven vertex.
[[nodiscard]] ScratchVector<std::uint8_t> proven_corners(const Soup& soup);

/// `proven_corners`, and each triangle's neighbour across each of its edges that has a proven
/// end (-1 for the others): across[t][k] is the triangle on the other side of the edge from
/// corner k to corner k + 1 (mod 3), which runs the other way there (a proven star is a closed
/// fan, so an edge at a proven vertex has exactly two triangles). And for each triangle whose
/// corner 0 is proven, the signs of its normal's components, exactly (the star's proof has
/// their products at hand): bit 2k (2k + 1) of turns[t] when orient2d of its corners dropping
/// axis k is positive (negative); 0 for the other triangles.
/// With `StarOrder::leaf`, `across` and `turns` are indexed by the triangles' positions in the
/// leaf order of `soup.tree` (`items()`), and `across` holds positions too (still -1 where no
/// neighbour is known): the order the patch proofs read them in, written so by the proofs
/// instead of copied into it afterwards (a scattered pass and 3 MB more at two 131k-triangle
/// spheres). `corners` is by triangle either way.
struct ProvenStars {
  ScratchVector<std::uint8_t> corners;
  ScratchVector<std::array<std::int32_t, 3>> across;
  ScratchVector<std::uint8_t> turns;
};
enum class StarOrder : std::uint8_t { triangle, leaf };
[[nodiscard]] ProvenStars proven_stars(const Soup& soup, StarOrder order = StarOrder::triangle);

/// The filters of the proofs, which share the differences dk = wk - v of the ring's vertices
/// from the apex and the products of consecutive ones, ck = dk x d(k+1) as six products of
/// doubles: every test of a star is a sign of ck (a sector's turn in a projection) or of
/// d(k+2) . ck (a bend of the ring). Inline for the proofs' loop; declared here for their tests.
struct RingProducts {
  double yz, zy, zx, xz, xy, yx;  ///< dk.y d(k+1).z, dk.z d(k+1).y, ...
};
[[nodiscard]] inline RingProducts ring_products(const std::array<double, 3>& a,
                                                const std::array<double, 3>& b) {
  return {a[1] * b[2], a[2] * b[1], a[2] * b[0], a[0] * b[2], a[0] * b[1], a[1] * b[0]};
}

/// The sign of component `axis` of ck, which is orient2d(v, wk, w(k+1)) in the projection
/// dropping that axis (`drop_axis`: the other two in cyclic order), where a filter decides it:
/// orient2d's own (Shewchuk's stage A of orient2d(wk, w(k+1), v), pivot v, a cyclic turn of
/// the same three points, on the shared differences and products, with the same bound
/// (3 + 32 eps) eps (|left| + |right|) + DBL_MIN); nothing where it cannot.
[[nodiscard]] inline std::optional<Sign> filtered_turn(const RingProducts& c, int axis) {
  constexpr double kBound =
      (3.0 + 32.0 * predicates::unit_roundoff<double>)*predicates::unit_roundoff<double>;
  const double left = axis == 0 ? c.yz : axis == 1 ? c.zx : c.xy;
  const double right = axis == 0 ? c.zy : axis == 1 ? c.xz : c.yx;
  const double det = left - right;
  const double errbound = kBound * (std::fabs(left) + std::fabs(right)) + DBL_MIN;
  if (det > errbound) return Sign::positive;
  if (-det > errbound) return Sign::negative;
  return std::nullopt;
}

/// The sign of det(dk, d(k+1), d(k+2)) = d(k+2) . ck (`t` = d(k+2)), which is
/// orient3d(v, wk, w(k+1), w(k+2)), where a filter decides it. (That determinant is Shewchuk's
/// orient3d of wk, w(k+1), w(k+2), v, pivot v; contain's orient3d is minus Shewchuk's, and
/// moving v from last to first is an odd permutation: the two sign changes cancel.) Shewchuk's
/// stage A expands along the pivot-less column z; here along the row d(k+2), the same evaluation
/// (three differences, each times a difference of two products of differences, summed left to
/// right) with the variables renamed, so his bound (7 + 56 eps) eps * permanent holds with this
/// expansion's permanent; raised as orient3d's to (7 + 64 eps) eps for an underflow guard DBL_MIN
/// scaled by the row's multipliers.
[[nodiscard]] inline std::optional<Sign> filtered_bend(const RingProducts& c,
                                                       const std::array<double, 3>& t) {
  constexpr double kBound =
      (7.0 + 64.0 * predicates::unit_roundoff<double>)*predicates::unit_roundoff<double>;
  const double det = t[0] * (c.yz - c.zy) + t[1] * (c.zx - c.xz) + t[2] * (c.xy - c.yx);
  const double ax = std::fabs(t[0]), ay = std::fabs(t[1]), az = std::fabs(t[2]);
  const double permanent = ax * (std::fabs(c.yz) + std::fabs(c.zy)) +
                           ay * (std::fabs(c.zx) + std::fabs(c.xz)) +
                           az * (std::fabs(c.xy) + std::fabs(c.yx));
  const double errbound = kBound * permanent + DBL_MIN * (1.0 + ax + ay + az);
  if (det > errbound) return Sign::positive;
  if (-det > errbound) return Sign::negative;
  return std::nullopt;
}

/// Whether `intersect_pair` would give triangles t and u (t < u) a constraint or a coplanar
/// partner, or make a crossing point on the way (for the tests; defined in intersect.cpp).
[[nodiscard]] bool pair_gives_work(const Soup& soup, std::int32_t t, std::int32_t u);

}  // namespace contain::clip::solid
