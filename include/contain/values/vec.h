#pragma once
/// \file
/// Points and vectors in 2D and 3D. Plain aggregates of doubles; arithmetic here is ordinary
/// floating point and is never used to decide topology (that is `predicates/`).

#include <cmath>

namespace contain::values {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

[[nodiscard]] constexpr Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
[[nodiscard]] constexpr Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
[[nodiscard]] constexpr Vec2 operator-(Vec2 a) {
  return {-a.x, -a.y};
}
[[nodiscard]] constexpr Vec2 operator*(double s, Vec2 a) {
  return {s * a.x, s * a.y};
}
[[nodiscard]] constexpr Vec2 operator*(Vec2 a, double s) {
  return {s * a.x, s * a.y};
}
[[nodiscard]] constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
/// z component of the 3D cross product: positive when b is counter-clockwise from a.
[[nodiscard]] constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
[[nodiscard]] inline double length(Vec2 a) {
  return std::hypot(a.x, a.y);
}
[[nodiscard]] constexpr double squared_length(Vec2 a) {
  return dot(a, a);
}

[[nodiscard]] constexpr Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
[[nodiscard]] constexpr Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
[[nodiscard]] constexpr Vec3 operator-(Vec3 a) {
  return {-a.x, -a.y, -a.z};
}
[[nodiscard]] constexpr Vec3 operator*(double s, Vec3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
[[nodiscard]] constexpr Vec3 operator*(Vec3 a, double s) {
  return {s * a.x, s * a.y, s * a.z};
}
/// The coordinate of v along axis 0 (x), 1 (y) or 2 (z).
[[nodiscard]] constexpr double component(Vec3 v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}
/// The coordinate of v along axis 0 (x), 1 (y) or 2 (z), to assign.
[[nodiscard]] constexpr double& component_ref(Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}
[[nodiscard]] constexpr double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
[[nodiscard]] constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
[[nodiscard]] inline double length(Vec3 a) {
  return std::sqrt(dot(a, a));
}
[[nodiscard]] constexpr double squared_length(Vec3 a) {
  return dot(a, a);
}

/// True when every coordinate is finite (no NaN, no infinity).
[[nodiscard]] inline bool is_finite(Vec2 a) {
  return std::isfinite(a.x) && std::isfinite(a.y);
}
[[nodiscard]] inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::cross;
using values::dot;
using values::is_finite;
using values::length;
using values::squared_length;
using values::Vec2;
using values::Vec3;
}  // namespace contain
