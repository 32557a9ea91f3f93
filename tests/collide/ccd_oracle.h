#pragma once
// Exact continuous collision in GMP rationals, by another route than the library's: the
// coplanarity cubic's roots are isolated by Sturm sequences over the rationals; at each root the
// inclusion is decided in a coordinate projection chosen by the sign of the normal there
// (orient2d of the projected points, quadratic in time), or, where the normal vanishes, by
// point-on-segment tests on the components; signs at roots by refinement and gcds
// (tests/support/exact_polynomial.h). Where the four points stay coplanar, every root in [0, 1]
// of every polynomial of the decision, and 0, is a candidate. The earliest contact is rounded
// down to a double by binary search over the doubles, each compared with the root exactly.

#include <array>
#include <optional>

#include "contain/values/vec.h"

namespace contain::test {

/// Points in the benchmark's row order: for vertex-face v(0), f0(0), f1(0), f2(0), v(1), f0(1),
/// f1(1), f2(1); for edge-edge a0(0), a1(0), b0(0), b1(0), a0(1), a1(1), b0(1), b1(1).
using CcdQuery = std::array<Vec3, 8>;

/// The largest double <= the earliest time in [0, 1] at which the vertex lies in the closed
/// triangle, or nothing when it never does.
[[nodiscard]] std::optional<double> exact_vertex_face_time(const CcdQuery& q);
/// The same for two closed segments sharing a point.
[[nodiscard]] std::optional<double> exact_edge_edge_time(const CcdQuery& q);

}  // namespace contain::test
