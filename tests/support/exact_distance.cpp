#include "support/exact_distance.h"

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

namespace contain::test {

namespace {

QVec3 sub(const QVec3& a, const QVec3& b) {
  return qsub(a, b);
}
mpq_class dot(const QVec3& a, const QVec3& b) {
  return qdot(a, b);
}

QVec3 add_scaled(const QVec3& a, const mpq_class& s, const QVec3& d) {
  return {a.x + s * d.x, a.y + s * d.y, a.z + s * d.z};
}
QVec2 sub(const QVec2& a, const QVec2& b) {
  return {a.x - b.x, a.y - b.y};
}
mpq_class dot(const QVec2& a, const QVec2& b) {
  return a.x * b.x + a.y * b.y;
}

// Point-segment with the clamped parameter t = (p - a).(b - a) / |b - a|^2.
template <class Q>
Q closest_on_segment(const Q& p, const Q& a, const Q& b) {
  const Q d = sub(b, a);
  const mpq_class len2 = dot(d, d);
  if (len2 == 0) return a;
  mpq_class t = dot(sub(p, a), d) / len2;
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  Q out = a;
  if constexpr (requires { out.z; }) {
    out = {a.x + t * d.x, a.y + t * d.y, a.z + t * d.z};
  } else {
    out = {a.x + t * d.x, a.y + t * d.y};
  }
  return out;
}

// x rounded to a double by exact comparisons with the midpoints of a candidate's neighbours.
double round_by_midpoints(double c, auto&& compare_with_midpoint) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 4096; ++step) {
    // lower boundary
    if (c != -kInf) {
      mpq_class m;
      if (c == kInf) {
        m = mpq_class(DBL_MAX) + mpq_class(std::ldexp(1.0, 970));
      } else if (c == -DBL_MAX) {
        m = -(mpq_class(DBL_MAX) + mpq_class(std::ldexp(1.0, 970)));
      } else {
        m = (mpq_class(c) + mpq_class(std::nextafter(c, -kInf))) / 2;
      }
      const int s = compare_with_midpoint(m);  // sign of value - m
      if (s < 0) {
        c = c == kInf ? DBL_MAX : std::nextafter(c, -kInf);
        continue;
      }
      if (s == 0) {
        const double lower = c == kInf ? DBL_MAX : std::nextafter(c, -kInf);
        return (std::bit_cast<std::uint64_t>(lower) & 1U) == 0 ? lower : c;
      }
    }
    if (c != kInf) {
      mpq_class m;
      if (c == DBL_MAX) {
        m = mpq_class(DBL_MAX) + mpq_class(std::ldexp(1.0, 970));
      } else if (c == -kInf) {
        m = -(mpq_class(DBL_MAX) + mpq_class(std::ldexp(1.0, 970)));
      } else {
        m = (mpq_class(c) + mpq_class(std::nextafter(c, kInf))) / 2;
      }
      const int s = compare_with_midpoint(m);
      if (s > 0) {
        c = c == -kInf ? -DBL_MAX : std::nextafter(c, kInf);
        continue;
      }
      if (s == 0) {
        const double upper = c == DBL_MAX ? kInf : std::nextafter(c, kInf);
        return (std::bit_cast<std::uint64_t>(c) & 1U) == 0 ? c : upper;
      }
    }
    return c;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

ExactClosest3 exact_closest(Vec3 p, const Triangle3& t) {
  const QVec3 qp = exact(p), a = exact(t.a), b = exact(t.b), c = exact(t.c);
  // Projection onto the plane: p - a = s u + r v + normal part, from the normal equations.
  const QVec3 u = sub(b, a), v = sub(c, a), w = sub(qp, a);
  const mpq_class uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
  const mpq_class det = uu * vv - uv * uv;
  if (det != 0) {
    const mpq_class s = (wu * vv - wv * uv) / det;
    const mpq_class r = (wv * uu - wu * uv) / det;
    if (s >= 0 && r >= 0 && s + r <= 1) {
      const QVec3 x = add_scaled(add_scaled(a, s, u), r, v);
      const QVec3 d = sub(qp, x);
      return {dot(d, d), x};
    }
  }
  ExactClosest3 best;
  bool have = false;
  const QVec3 corners[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const QVec3 x = closest_on_segment(qp, corners[e], corners[(e + 1) % 3]);
    const QVec3 d = sub(qp, x);
    const mpq_class d2 = dot(d, d);
    if (!have || d2 < best.squared_distance) {
      best = {d2, x};
      have = true;
    }
  }
  return best;
}

ExactClosest3 exact_closest(Vec3 p, const Segment3& s) {
  const QVec3 qp = exact(p);
  const QVec3 x = closest_on_segment(qp, exact(s.a), exact(s.b));
  const QVec3 d = sub(qp, x);
  return {dot(d, d), x};
}

ExactClosest2 exact_closest(Vec2 p, const Segment2& s) {
  const QVec2 qp = exact(p);
  const QVec2 x = closest_on_segment(qp, exact(s.a), exact(s.b));
  const QVec2 d = sub(qp, x);
  return {dot(d, d), x};
}

mpq_class exact_squared_distance(const Segment3& s, const Segment3& t) {
  mpq_class best = exact_closest(s.a, t).squared_distance;
  for (const mpq_class& d : {exact_closest(s.b, t).squared_distance,
                             exact_closest(t.a, Segment3{s.a, s.b}).squared_distance,
                             exact_closest(t.b, Segment3{s.a, s.b}).squared_distance}) {
    if (d < best) best = d;
  }
  const QVec3 a = exact(s.a), c = exact(t.a);
  const QVec3 u = sub(exact(s.b), a), v = sub(exact(t.b), c), r = sub(a, c);
  // minimise |r + x u - y v|^2: [uu -uv; uv -vv] (x, y) = (-ru, -rv)
  const mpq_class uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), ru = dot(r, u), rv = dot(r, v);
  const mpq_class det = uu * vv - uv * uv;
  if (det != 0) {
    const mpq_class x = (uv * rv - vv * ru) / det;
    const mpq_class y = (uu * rv - uv * ru) / det;
    if (x >= 0 && x <= 1 && y >= 0 && y <= 1) {
      const QVec3 d = sub(add_scaled(r, x, u), QVec3{y * v.x, y * v.y, y * v.z});
      const mpq_class d2 = dot(d, d);
      if (d2 < best) best = d2;
    }
  }
  return best;
}

mpq_class exact_squared_distance(const Segment2& s, const Segment2& t) {
  const Segment3 s3{{s.a.x, s.a.y, 0}, {s.b.x, s.b.y, 0}};
  const Segment3 t3{{t.a.x, t.a.y, 0}, {t.b.x, t.b.y, 0}};
  return exact_squared_distance(s3, t3);
}

// A first guess within a few ulps over the whole range (subnormals and overflow included).
double guess_of(const mpf_class& f) {
  long e = 0;
  const double d = mpf_get_d_2exp(&e, f.get_mpf_t());
  if (e > 2000)
    return d > 0 ? std::numeric_limits<double>::infinity()
                 : -std::numeric_limits<double>::infinity();
  if (e < -2000) return 0.0;
  return std::ldexp(d, static_cast<int>(e));
}

double nearest_double(const mpq_class& x) {
  return round_by_midpoints(guess_of(mpf_class(x, 256)),
                            [&](const mpq_class& m) { return sgn(x - m); });
}

double nearest_double_sqrt(const mpq_class& x) {
  const double guess = guess_of(sqrt(mpf_class(x, 256)));
  return round_by_midpoints(guess, [&](const mpq_class& m) {
    if (m < 0) return 1;
    return sgn(x - m * m);
  });
}

mpq_class exact_squared_distance(Vec3 p, const Box3& b) {
  const double at[3] = {p.x, p.y, p.z};
  const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
  mpq_class sum = 0;
  for (int k = 0; k < 3; ++k) {
    mpq_class gap = 0;
    if (at[k] < lo[k]) gap = mpq_class(lo[k]) - mpq_class(at[k]);
    if (at[k] > hi[k]) gap = mpq_class(at[k]) - mpq_class(hi[k]);
    sum += gap * gap;
  }
  return sum;
}

}  // namespace contain::test
