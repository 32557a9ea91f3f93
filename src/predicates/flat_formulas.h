#pragma once
// The squared distance between two flats as a quotient N / D of polynomials in the input
// doubles, and the coordinates of the closest points as quotients over the same D, written once
// over the number type T: Bounded (the filter), BasicBounded<long double> (the first rounding
// stage) and BigFloat (exact). The table of formulas is in
// include/contain/predicates/squared_distance.h; the closest points:
//   point p, line a b:     a + t (b - a),  t = ((p - a) . (b - a)) / |b - a|^2
//   point p, plane a b c:  p - n s / |n|^2, s = (p - a) . n
//   line a b, line c d:    a + s (b - a) and c + t (d - c), s = (r x v) . m / |m|^2,
//                          t = (r x u) . m / |m|^2, r = c - a, u = b - a, v = d - c, m = u x v
// (X - Y is parallel to m; cross with v, resp. u, and dot with m).

#include <array>
#include <utility>

#include "contain/predicates/squared_distance.h"

namespace contain::predicates::detail {

template <class T>
struct V3 {
  T x, y, z;
};
template <class T>
struct V2 {
  T x, y;
};

template <class T>
V3<T> lift(Vec3 a) {
  return {T(a.x), T(a.y), T(a.z)};
}
template <class T>
V2<T> lift(Vec2 a) {
  return {T(a.x), T(a.y)};
}
template <class T>
V3<T> sub(Vec3 a, Vec3 b) {
  return {T(a.x) - T(b.x), T(a.y) - T(b.y), T(a.z) - T(b.z)};
}
template <class T>
V2<T> sub(Vec2 a, Vec2 b) {
  return {T(a.x) - T(b.x), T(a.y) - T(b.y)};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}
template <class T>
T dot(const V2<T>& a, const V2<T>& b) {
  return a.x * b.x + a.y * b.y;
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T cross(const V2<T>& a, const V2<T>& b) {
  return a.x * b.y - a.y * b.x;
}

template <class T>
struct Quotient {
  T num;
  T den;
};

// The point-flat pairs with the point first; `normalized` swaps a line-point or plane-point pair.
inline FlatPair3 normalized(const FlatPair3& x) {
  if (x.a.size > x.b.size) return {x.b, x.a};
  return x;
}
inline FlatPair2 normalized(const FlatPair2& x) {
  if (x.a.size > x.b.size) return {x.b, x.a};
  return x;
}

template <class T>
Quotient<T> squared_distance(const FlatPair3& pair) {
  const FlatPair3 x = normalized(pair);
  const Vec3 p = x.a.points[0];
  const std::array<Vec3, 3>& q = x.b.points;
  if (x.a.size == 1) {
    switch (x.b.size) {
      case 1: {
        const V3<T> d = sub<T>(p, q[0]);
        return {dot(d, d), T(1.0)};
      }
      case 2: {
        const V3<T> u = sub<T>(q[1], q[0]);
        const V3<T> c = cross(sub<T>(p, q[0]), u);
        return {dot(c, c), dot(u, u)};
      }
      default: {
        const V3<T> n = cross(sub<T>(q[1], q[0]), sub<T>(q[2], q[0]));
        const T s = dot(sub<T>(p, q[0]), n);
        return {s * s, dot(n, n)};
      }
    }
  }
  if (x.b.size == 3) return {T(0.0), T(1.0)};  // a line crossing a plane
  // line a0 a1, line b0 b1
  const V3<T> m = cross(sub<T>(x.a.points[1], x.a.points[0]), sub<T>(q[1], q[0]));
  const T s = dot(sub<T>(q[0], x.a.points[0]), m);
  return {s * s, dot(m, m)};
}

template <class T>
Quotient<T> squared_distance(const FlatPair2& pair) {
  const FlatPair2 x = normalized(pair);
  const Vec2 p = x.a.points[0];
  const std::array<Vec2, 2>& q = x.b.points;
  if (x.b.size == 1) {
    const V2<T> d = sub<T>(p, q[0]);
    return {dot(d, d), T(1.0)};
  }
  if (x.a.size == 2) return {T(0.0), T(1.0)};  // two crossing lines
  const V2<T> u = sub<T>(q[1], q[0]);
  const T c = cross(u, sub<T>(p, q[0]));
  return {c * c, dot(u, u)};
}

// The closest points on a and on b as coordinate numerators over one denominator (a point of a
// point flat has denominator 1 and is returned as numerators times the common denominator).
template <class T>
struct ClosestQuotients3 {
  std::array<T, 3> a;
  std::array<T, 3> b;
  T den;
};

template <class T>
ClosestQuotients3<T> closest_points(const FlatPair3& pair) {
  const bool swapped = pair.a.size > pair.b.size;
  const FlatPair3 x = normalized(pair);
  ClosestQuotients3<T> out;
  const std::array<Vec3, 3>& q = x.b.points;
  auto scaled_point = [](Vec3 v, const T& den) {
    return std::array<T, 3>{T(v.x) * den, T(v.y) * den, T(v.z) * den};
  };
  if (x.a.size == 1) {
    const Vec3 p = x.a.points[0];
    switch (x.b.size) {
      case 1:
        out.den = T(1.0);
        out.a = {T(p.x), T(p.y), T(p.z)};
        out.b = {T(q[0].x), T(q[0].y), T(q[0].z)};
        break;
      case 2: {
        const V3<T> u = sub<T>(q[1], q[0]);
        const T t = dot(sub<T>(p, q[0]), u);
        out.den = dot(u, u);
        out.a = scaled_point(p, out.den);
        out.b = {T(q[0].x) * out.den + u.x * t, T(q[0].y) * out.den + u.y * t,
                 T(q[0].z) * out.den + u.z * t};
        break;
      }
      default: {
        const V3<T> n = cross(sub<T>(q[1], q[0]), sub<T>(q[2], q[0]));
        const T s = dot(sub<T>(p, q[0]), n);
        out.den = dot(n, n);
        out.a = scaled_point(p, out.den);
        out.b = {T(p.x) * out.den - n.x * s, T(p.y) * out.den - n.y * s,
                 T(p.z) * out.den - n.z * s};
        break;
      }
    }
  } else if (x.b.size == 3) {
    // The line p -> p1 crosses the plane: x = p + (p1 - p) s, s = ((a - p) . n) / ((p1 - p) . n),
    // the denominator positive by the pair's precondition.
    const Vec3 p0 = x.a.points[0];
    const V3<T> d = sub<T>(x.a.points[1], p0);
    const V3<T> n = cross(sub<T>(q[1], q[0]), sub<T>(q[2], q[0]));
    const T num = dot(sub<T>(q[0], p0), n);
    out.den = dot(d, n);
    out.a = {T(p0.x) * out.den + d.x * num, T(p0.y) * out.den + d.y * num,
             T(p0.z) * out.den + d.z * num};
    out.b = out.a;
  } else {
    const Vec3 a0 = x.a.points[0];
    const Vec3 c0 = q[0];
    const V3<T> u = sub<T>(x.a.points[1], a0);
    const V3<T> v = sub<T>(q[1], c0);
    const V3<T> m = cross(u, v);
    const V3<T> r = sub<T>(c0, a0);
    const T s = dot(cross(r, v), m);
    const T t = dot(cross(r, u), m);
    out.den = dot(m, m);
    out.a = {T(a0.x) * out.den + u.x * s, T(a0.y) * out.den + u.y * s, T(a0.z) * out.den + u.z * s};
    out.b = {T(c0.x) * out.den + v.x * t, T(c0.y) * out.den + v.y * t, T(c0.z) * out.den + v.z * t};
  }
  if (swapped) std::swap(out.a, out.b);
  return out;
}

template <class T>
struct ClosestQuotients2 {
  std::array<T, 2> a;
  std::array<T, 2> b;
  T den;
};

template <class T>
ClosestQuotients2<T> closest_points(const FlatPair2& pair) {
  const bool swapped = pair.a.size > pair.b.size;
  const FlatPair2 x = normalized(pair);
  ClosestQuotients2<T> out;
  const Vec2 p = x.a.points[0];
  const std::array<Vec2, 2>& q = x.b.points;
  if (x.b.size == 1) {
    out.den = T(1.0);
    out.a = {T(p.x), T(p.y)};
    out.b = {T(q[0].x), T(q[0].y)};
  } else if (x.a.size == 2) {
    // Crossing lines: x = a + s (a1 - a), s = cross(c - a, v) / cross(u, v), u = a1 - a,
    // v = c1 - c, the denominator positive by the pair's precondition.
    const V2<T> u = sub<T>(x.a.points[1], p);
    const V2<T> v = sub<T>(q[1], q[0]);
    const T num = cross(sub<T>(q[0], p), v);
    out.den = cross(u, v);
    out.a = {T(p.x) * out.den + u.x * num, T(p.y) * out.den + u.y * num};
    out.b = out.a;
  } else {
    const V2<T> u = sub<T>(q[1], q[0]);
    const T t = dot(sub<T>(p, q[0]), u);
    out.den = dot(u, u);
    out.a = {T(p.x) * out.den, T(p.y) * out.den};
    out.b = {T(q[0].x) * out.den + u.x * t, T(q[0].y) * out.den + u.y * t};
  }
  if (swapped) std::swap(out.a, out.b);
  return out;
}

}  // namespace contain::predicates::detail
