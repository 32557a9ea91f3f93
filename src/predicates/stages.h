#pragma once
// The stages behind each public predicate, exposed to the tests so that every stage can be
// checked against the exact oracle on its own (the filter would otherwise answer most calls).
//
//   filter    a few floating-point operations and a proven error bound (in each .cpp);
//   expansion exact floating-point expansions (expansion.h), exact when the inputs pass
//             in_expansion_range for the predicate's degree;
//   big       BigFloat (big_float.h), exact for every finite input.
//
// The public predicate runs filter -> expansion (inputs in range, or rescaled into it by a
// power of two when the predicate is homogeneous and the exponents allow) -> big. Bounds and
// regimes are derived in docs/robustness.md.

#include <cfloat>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/plane.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::predicates::detail {

/// Added to every filter bound (scaled by the largest factor a product's rounding error can be
/// multiplied by) so that the bounds stay sound when products underflow: a product's absolute
/// error is then at most 2^-1075 rather than relative, and DBL_MIN = 2^-1022 covers that with a
/// margin of 2^53. Results below it in magnitude go to the exact stages.
inline constexpr double kUnderflowGuard = DBL_MIN;

[[nodiscard]] Sign orient2d_expansion(Vec2 a, Vec2 b, Vec2 c);
[[nodiscard]] Sign orient2d_big(Vec2 a, Vec2 b, Vec2 c);

[[nodiscard]] Sign orient3d_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
[[nodiscard]] Sign orient3d_big(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

[[nodiscard]] Sign side_of_plane_expansion(const Plane& plane, Vec3 p);
[[nodiscard]] Sign side_of_plane_big(const Plane& plane, Vec3 p);
[[nodiscard]] Sign side_of_line_expansion(const HalfPlane& half_plane, Vec2 p);
[[nodiscard]] Sign side_of_line_big(const HalfPlane& half_plane, Vec2 p);

[[nodiscard]] Sign side_of_sphere_expansion(const Sphere& sphere, Vec3 p);
[[nodiscard]] Sign side_of_sphere_big(const Sphere& sphere, Vec3 p);
[[nodiscard]] Sign side_of_circle_expansion(const Circle& circle, Vec2 p);
[[nodiscard]] Sign side_of_circle_big(const Circle& circle, Vec2 p);

[[nodiscard]] Sign cross_dot_expansion(Vec3 a, Vec3 b, Vec3 p, Vec3 c);
[[nodiscard]] Sign cross_dot_big(Vec3 a, Vec3 b, Vec3 p, Vec3 c);

/// The exact stages after the filter (range check, then expansion, rescaled expansion or big).
[[nodiscard]] Sign side_of_sphere_exact(const Sphere& s, Vec3 p);
[[nodiscard]] Sign side_of_circle_exact(const Circle& s, Vec2 p);
[[nodiscard]] Sign cross_dot_exact(Vec3 a, Vec3 b, Vec3 p, Vec3 c);
[[nodiscard]] Sign side_of_plane_exact(const Plane& h, Vec3 p);
[[nodiscard]] Sign side_of_line_exact(const HalfPlane& h, Vec2 p);

/// The ratio (c - pk) / (qk - pk) of a crossing, shared by its coordinates: rho0 rounded
/// (`crossing_ratio`, one division), then on demand (`refine_ratio`) rho0 + rho1 within `error`,
/// a double-double with a running bound. Not `valid` when a difference is outside
/// [2^-200, 2^200] in magnitude (zero included).
struct CrossingRatio {
  double pk = 0.0, qk = 0.0, c = 0.0;
  double inverse = 0.0;  // fl(1 / fl(qk - pk))
  double rho0 = 0.0;
  double rho1 = 0.0;
  double error = 0.0;
  bool valid = false;
  bool refined = false;
};
[[nodiscard]] CrossingRatio crossing_ratio(double pk, double qk, double c);
void refine_ratio(CrossingRatio& rho);
/// The double nearest to p + (q - p) rho, written to out when a bound proves it: in double from
/// rho0 (quick), or in double-double from a refined ratio.
[[nodiscard]] bool rounded_offset_quick(double p, double q, const CrossingRatio& rho, double& out);
[[nodiscard]] bool rounded_offset(double p, double q, const CrossingRatio& rho, double& out);
/// The filters of rounded_axis_crossing in turn (quick, then double-double): the double nearest
/// to p + (q - p)(c - pk) / (qk - pk) (pk != qk, c between them), written to out when a bound
/// proves it (true); false hands the case to the long double and exact stages. Refuses differences
/// outside [2^-200, 2^200] in magnitude and |p| > 2^200.
[[nodiscard]] bool rounded_crossing_filter(double p, double q, double pk, double qk, double c,
                                           double& out);
/// The stages after it: long double with a priori bounds, then exact BigFloat comparisons.
[[nodiscard]] double rounded_crossing_exact(double p, double q, double pk, double qk, double c);

}  // namespace contain::predicates::detail
