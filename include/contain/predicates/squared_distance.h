#pragma once
/// \file
/// Exact comparisons of squared distances between flats (points, lines, planes), the decisions
/// of every distance query: which feature is closest, is the distance at most D.
///
/// The distance from a point to a triangle (or between two triangles, two segments) is the
/// distance between the two flats that carry the closest features: the affine hulls of a vertex,
/// of an edge or of a face. Once those features are known exactly (`closest_feature.h`), the
/// squared distance is a quotient N / D of two polynomials in the input doubles:
///
/// | pair | N | D |
/// | --- | --- | --- |
/// | point p, point q | \|p - q\|^2 | 1 |
/// | point p, line a b | \|(p - a) x (b - a)\|^2 | \|b - a\|^2 |
/// | point p, plane a b c | ((p - a) . n)^2, n = (b - a) x (c - a) | \|n\|^2 |
/// | line a b, line c d | ((c - a) . m)^2, m = (b - a) x (d - c) | \|m\|^2 |
/// | 2D point p, line a b | ((b - a) x (p - a))^2 | \|b - a\|^2 |
/// | line crossing a plane, 2D lines crossing | 0 | 1 |
///
/// Comparisons are signs of N1 D2 - N2 D1 (degree up to 10) and of N - d^2 D, exact on the given
/// doubles: a running-error filter (a proven bound carried through the evaluation), then
/// big-number arithmetic (every finite double, any exponents). Derivation: docs/robustness.md,
/// "Distance".

#include <array>
#include <cstdint>

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The affine hull of 1, 2 or 3 points: a point, a line, a plane.
/// Preconditions (not checked): a line's two points differ; a plane's three are not collinear.
struct Flat3 {
  std::array<Vec3, 3> points{};
  std::int8_t size = 1;  ///< 1 point, 2 line, 3 plane
};

/// A point or a line in the plane. Precondition: a line's two points differ.
struct Flat2 {
  std::array<Vec2, 2> points{};
  std::int8_t size = 1;  ///< 1 point, 2 line
};

/// Two flats whose squared distance is meant: point-point, point-line, point-plane (either
/// order) or line-line; two lines must not be parallel (their distance is then a point-line
/// distance, which the callers use). A line and a plane (in this order) stand for a segment
/// crossing a triangle: their distance is 0 and their closest point the crossing; precondition:
/// the line's first point lies strictly below the plane and its second strictly above
/// (orient3d < 0, resp. > 0, with the plane's three points).
struct FlatPair3 {
  Flat3 a;
  Flat3 b;
};
/// In the plane: point-point, point-line (either order), or two lines that cross (distance 0,
/// the closest point their crossing; precondition: cross(a1 - a0, b1 - b0) > 0).
struct FlatPair2 {
  Flat2 a;
  Flat2 b;
};

[[nodiscard]] constexpr Flat3 point_flat(Vec3 p) {
  return {{p, {}, {}}, 1};
}
[[nodiscard]] constexpr Flat3 line_flat(Vec3 a, Vec3 b) {
  return {{a, b, {}}, 2};
}
[[nodiscard]] constexpr Flat3 plane_flat(Vec3 a, Vec3 b, Vec3 c) {
  return {{a, b, c}, 3};
}
[[nodiscard]] constexpr Flat2 point_flat(Vec2 p) {
  return {{p, {}}, 1};
}
[[nodiscard]] constexpr Flat2 line_flat(Vec2 a, Vec2 b) {
  return {{a, b}, 2};
}

/// True when x and y are the same point set: the same points in some order (a vertex, an edge
/// or a face shared by neighbouring triangles, or met twice by one search). Their distances to
/// anything are then equal without arithmetic.
[[nodiscard]] bool same_flat(const Flat3& x, const Flat3& y);
[[nodiscard]] bool same_flat(const Flat2& x, const Flat2& y);

/// Sign of dist^2(x) - dist^2(y), exactly: negative when x's flats are closer to each other
/// than y's. O(1); the exact stage runs only when the two are within the filter's error.
/// Pairs of the same flats (same_flat on both sides) are equal at once: the filter cannot see
/// an exact tie, and the candidates of one triangle pair or one contact often repeat a pair.
[[nodiscard]] Sign compare_squared_distances(const FlatPair3& x, const FlatPair3& y);
[[nodiscard]] Sign compare_squared_distances(const FlatPair2& x, const FlatPair2& y);

/// Sign of dist^2(x) - d^2, exactly (d is a double, its sign ignored): the clearance test
/// "distance at most d" is `!= Sign::positive`.
[[nodiscard]] Sign compare_squared_distance(const FlatPair3& x, double d);
[[nodiscard]] Sign compare_squared_distance(const FlatPair2& x, double d);

/// True when the squared distance of x is exactly zero (the flats meet).
[[nodiscard]] bool flats_meet(const FlatPair3& x);
[[nodiscard]] bool flats_meet(const FlatPair2& x);

}  // namespace contain::predicates
