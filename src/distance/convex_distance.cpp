#include "contain/distance/convex_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/bound/gjk.h"
#include "contain/inside/point_in_convex.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "distance/flat_answer.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool lexicographic_less(Vec3 p, Vec3 q) {
  return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
}

double max_abs(std::span<const Vec3> points) {
  double m = 0.0;
  for (const Vec3& v : points)
    m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return m;
}

Triangle3 triangle_of(std::span<const Vec3> v, const TriangleIndices& t) {
  return {v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
          v[static_cast<std::size_t>(t[2])]};
}

// Exact location of q in the solid bounded by the outward faces (as inside::point_in_convex).
Location locate(const Mesh& faces, std::span<const Vec3> vertices, Vec3 q) {
  Location result = Location::inside;
  for (const TriangleIndices& t : faces.triangles) {
    const Triangle3 f = triangle_of(vertices, t);
    const Sign s = predicates::orient3d(f.a, f.b, f.c, q);
    if (s == Sign::positive) return Location::outside;
    if (s == Sign::zero) result = Location::boundary;
  }
  return result;
}

Vec3 support(std::span<const Vec3> vertices, Vec3 d) {
  Vec3 best = vertices[0];
  double best_dot = dot(d, best);
  for (const Vec3& p : vertices) {
    const double x = dot(d, p);
    if (x > best_dot) {
      best_dot = x;
      best = p;
    }
  }
  return best;
}

struct PairContender {
  std::int32_t a, b;
  double lo, hi;
};

}  // namespace

Result<ConvexDistance> ConvexDistance::prepare(const ConvexPolyhedron& polyhedron) {
  if (polyhedron.faces().empty()) {
    return Error{ErrorKind::unsupported,
                 "a convex polyhedron given by planes has no faces to measure to: build it from "
                 "a mesh"};
  }
  ConvexDistance out;
  out.polyhedron_ = polyhedron;
  std::vector<Vec3>& v = out.mesh_.vertices;
  for (const Triangle3& t : polyhedron.faces()) {
    v.push_back(t.a);
    v.push_back(t.b);
    v.push_back(t.c);
  }
  std::sort(v.begin(), v.end(), lexicographic_less);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  const auto index_of = [&](Vec3 p) {
    return static_cast<std::int32_t>(std::lower_bound(v.begin(), v.end(), p, lexicographic_less) -
                                     v.begin());
  };
  for (const Triangle3& t : polyhedron.faces())
    out.mesh_.triangles.push_back({index_of(t.a), index_of(t.b), index_of(t.c)});
  // Faces around each vertex (compressed rows), for the faces near GJK's closest simplices.
  out.face_start_.assign(v.size() + 1, 0);
  for (const TriangleIndices& t : out.mesh_.triangles)
    for (const std::int32_t k : t)
      ++out.face_start_[static_cast<std::size_t>(k) + 1];
  for (std::size_t k = 0; k < v.size(); ++k)
    out.face_start_[k + 1] += out.face_start_[k];
  out.face_list_.resize(static_cast<std::size_t>(out.face_start_.back()));
  std::vector<std::int32_t> fill(out.face_start_.begin(), out.face_start_.end() - 1);
  for (std::size_t f = 0; f < out.mesh_.triangles.size(); ++f)
    for (const std::int32_t k : out.mesh_.triangles[f])
      out.face_list_[static_cast<std::size_t>(fill[static_cast<std::size_t>(k)]++)] =
          static_cast<std::int32_t>(f);
  out.surface_ = MeshDistance(out.mesh_, {.signs = false});
  out.max_abs_ = max_abs(v);
  return out;
}

Closest3 ConvexDistance::query(Vec3 p, const PointQuery& query) const {
  Closest3 out =
      surface_.query(p, {.signed_distance = false, .closest_point = query.closest_point});
  if (query.signed_distance && std::isfinite(out.distance))
    detail::apply_sign(out, inside::point_in_convex(polyhedron_, p));
  return out;
}

void ConvexDistance::query(std::span<const Vec3> points, std::span<Closest3> out,
                           const PointQuery& query, const BatchOptions& options) const {
  const std::size_t n = std::min(points.size(), out.size());
  surface_.query(points.first(n), out.first(n),
                 {.signed_distance = false, .closest_point = query.closest_point}, options);
  if (!query.signed_distance) return;
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (std::isfinite(out[i].distance))
        detail::apply_sign(out[i], inside::point_in_convex(polyhedron_, points[i]));
  });
}

bool ConvexDistance::within(Vec3 p, double d) const {
  return surface_.within(p, d);
}

Result<Closest3> point_convex(Vec3 p, const ConvexPolyhedron& polyhedron, const PointQuery& query) {
  auto prepared = ConvexDistance::prepare(polyhedron);
  if (!prepared) return prepared.error();
  return prepared->query(p, query);
}

PairDistance3 ConvexDistance::pair(const ConvexDistance& a, const ConvexDistance& b,
                                   const Transform& tb, double within_d, bool* within_out) {
  PairDistance3 out;
  const std::span<const Vec3> va = a.mesh_.vertices;
  // B's vertices as placed: the doubles every decision is exact on.
  thread_local std::vector<Vec3> wb;
  wb.resize(b.mesh_.vertices.size());
  for (std::size_t i = 0; i < wb.size(); ++i)
    wb[i] = tb.apply(b.mesh_.vertices[i]);
  if (!std::all_of(wb.begin(), wb.end(), [](Vec3 p) { return is_finite(p); })) {
    out.distance = std::numeric_limits<double>::quiet_NaN();
    if (within_out) *within_out = false;
    return out;
  }

  // 1. Containment first, as MeshPairDistance: a vertex of one strictly inside the other solid
  // (one component each) makes the distance 0, the solids overlapping or nested.
  if (locate(a.mesh_, va, wb[0]) == Location::inside) {
    out.contact = PairContact::vertex_of_b_in_a;
    out.vertex = 0;
    out.point_a = out.point_b = wb[0];
    if (within_out) *within_out = true;
    return out;
  }
  if (locate(b.mesh_, wb, va[0]) == Location::inside) {
    out.contact = PairContact::vertex_of_a_in_b;
    out.vertex = 0;
    out.point_a = out.point_b = va[0];
    if (within_out) *within_out = true;
    return out;
  }

  // 2. GJK's guess: a direction v from B to A and the simplices of its closest points.
  const bound::GjkResult g =
      bound::gjk([&](Vec3 d) { return support(va, d); }, [&](Vec3 d) { return support(wb, d); });
  const double slack = detail::triangle_slack(std::max(a.max_abs_, max_abs(wb)));
  const auto face_a = [&](std::int32_t f) {
    return triangle_of(va, a.mesh_.triangles[static_cast<std::size_t>(f)]);
  };
  const auto face_b = [&](std::int32_t f) {
    return triangle_of(wb, b.mesh_.triangles[static_cast<std::size_t>(f)]);
  };
  const auto faces_around = [](const ConvexDistance& c, std::span<const Vec3> vertices, Vec3 p,
                               std::vector<std::int32_t>& faces) {
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      if (!(vertices[k] == p)) continue;
      for (std::int32_t i = c.face_start_[k]; i < c.face_start_[k + 1]; ++i)
        faces.push_back(c.face_list_[static_cast<std::size_t>(i)]);
    }
  };
  // A proven upper bound of the surfaces' distance: the least over the pairs of faces around
  // the simplices' points (one of them holds the closest pair when GJK has converged).
  double upper = kInf;
  {
    thread_local std::vector<std::int32_t> near_a, near_b;
    near_a.clear();
    near_b.clear();
    for (int i = 0; i < g.simplex_size; ++i) {
      faces_around(a, va, g.simplex_a[static_cast<std::size_t>(i)], near_a);
      faces_around(b, wb, g.simplex_b[static_cast<std::size_t>(i)], near_b);
    }
    for (const std::int32_t fa : near_a) {
      for (const std::int32_t fb : near_b) {
        double lo = 0, hi = 0;
        detail::triangle_pair_bounds(face_a(fa), face_b(fb), slack, lo, hi);
        upper = std::min(upper, hi);
      }
    }
  }

  // 3. The faces GJK's direction cannot rule out: a face f of A is at least its separation along
  // w = v from B's farthest vertex away (rounding bounded), so it is out when that exceeds the
  // upper bound; likewise for B's faces against A.
  thread_local std::vector<std::int32_t> keep_a, keep_b;
  keep_a.clear();
  keep_b.clear();
  const Vec3 w = g.v, y = g.point_b;
  const double ww = dot(w, w);
  const bool directed = !g.origin_inside && ww > 0 && std::isfinite(ww) && upper < kInf;
  double a_min = kInf, b_max = -kInf;
  if (directed) {
    for (const Vec3& p : va)
      a_min = std::min(a_min, detail::separation_bound(p, y, w, 1.0));
    for (const Vec3& p : wb)
      b_max = std::max(b_max, detail::separation_bound(p, y, w, -1.0));
  }
  for (std::size_t f = 0; f < a.mesh_.triangles.size(); ++f) {
    if (directed) {
      const Triangle3 t = face_a(static_cast<std::int32_t>(f));
      const double lo = std::min({detail::separation_bound(t.a, y, w, 1.0),
                                  detail::separation_bound(t.b, y, w, 1.0),
                                  detail::separation_bound(t.c, y, w, 1.0)});
      if (detail::squared_separation_lower(lo - b_max, ww) > upper) continue;
    }
    keep_a.push_back(static_cast<std::int32_t>(f));
  }
  for (std::size_t f = 0; f < b.mesh_.triangles.size(); ++f) {
    if (directed) {
      const Triangle3 t = face_b(static_cast<std::int32_t>(f));
      const double hi = std::max({detail::separation_bound(t.a, y, w, -1.0),
                                  detail::separation_bound(t.b, y, w, -1.0),
                                  detail::separation_bound(t.c, y, w, -1.0)});
      if (detail::squared_separation_lower(a_min - hi, ww) > upper) continue;
    }
    keep_b.push_back(static_cast<std::int32_t>(f));
  }

  // 4. The pairs of the faces left, bounded; then the exact stage among those that can be
  // closest, in the order of the distance-tie rule.
  const detail::SquaredBounds d2 = detail::squared_bounds(within_d);
  thread_local std::vector<PairContender> contenders;
  contenders.clear();
  double best = upper;
  for (const std::int32_t fa : keep_a) {
    const Triangle3 ta = face_a(fa);
    for (const std::int32_t fb : keep_b) {
      double lo = 0, hi = 0;
      detail::triangle_pair_bounds(ta, face_b(fb), slack, lo, hi);
      ++out.node_pairs;
      if (lo > best) continue;
      if (within_out && hi <= d2.lo) {
        *within_out = true;  // proven within d: no need to know which pair is closest
        return out;
      }
      contenders.push_back({fa, fb, lo, hi});
      best = std::min(best, hi);
    }
  }
  std::erase_if(contenders, [&](const PairContender& c) { return c.lo > best; });
  out.contenders = contenders.size();
  predicates::FlatPair3 winner{};
  bool have = false;
  for (const PairContender& c : contenders) {  // already in (a, b) order
    const predicates::FlatPair3 flats = predicates::closest_flats(face_a(c.a), face_b(c.b));
    if (!have || predicates::compare_squared_distances(flats, winner) == Sign::negative) {
      winner = flats;
      out.triangle_a = c.a;
      out.triangle_b = c.b;
      have = true;
    }
  }
  const bool touching = predicates::flats_meet(winner);
  if (within_out) {
    *within_out =
        touching || predicates::compare_squared_distance(winner, within_d) != Sign::positive;
    return out;
  }
  out.contact = touching ? PairContact::touching : PairContact::separate;
  out.distance = predicates::rounded_distance(winner);
  const predicates::ClosestPoints3 points = predicates::rounded_closest_points(winner);
  out.point_a = points.a;
  out.point_b = points.b;
  return out;
}

PairDistance3 convex_convex(const ConvexDistance& a, const ConvexDistance& b,
                            const Transform& transform_b) {
  return ConvexDistance::pair(a, b, transform_b, 0.0, nullptr);
}

bool convex_convex_within(const ConvexDistance& a, const ConvexDistance& b,
                          const Transform& transform_b, double d) {
  if (!(d >= 0)) return false;
  bool answer = false;
  (void)ConvexDistance::pair(a, b, transform_b, d, &answer);
  return answer;
}

}  // namespace contain::distance
