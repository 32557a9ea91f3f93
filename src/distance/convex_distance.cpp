#include "contain/distance/convex_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/bound/gjk.h"
#include "contain/inside/point_in_convex.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"
#include "distance/flat_answer.h"
#include "distance/least_contender.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

// The pair query in stages, each a function below; convex_convex and convex_convex_within
// compose them and differ only at stage 4 (within may stop at a pair proven close enough) and
// in how they read the winner:
//   0. place B's vertices by the transform (the doubles every decision is exact on);
//   1. containment: a vertex of one strictly inside the other (nested or overlapping);
//   2. GJK's guess and a proven upper bound from the faces around its closest simplices;
//   3. the faces GJK's direction cannot rule out against that bound;
//   4. the pairs of those faces, bounded in floating point: the contenders;
//   5. the exact stage among the contenders (predicates::closest_flats).

// A's faces as given, B's over its placed vertices: the doubles every decision is exact on.
struct PlacedPair {
  const ConvexPolyhedron& a;
  const ConvexPolyhedron& b;
  std::span<const Vec3> wb;  // B's vertices placed, wb[k] for b.vertices()[k]
  double slack;              // of computed closest points, over both (triangle_slack)

  [[nodiscard]] Triangle3 face_a(std::int32_t f) const { return a.face(f); }
  [[nodiscard]] Triangle3 face_b(std::int32_t f) const {
    const TriangleIndices& t = b.face_indices()[static_cast<std::size_t>(f)];
    return {wb[static_cast<std::size_t>(t[0])], wb[static_cast<std::size_t>(t[1])],
            wb[static_cast<std::size_t>(t[2])]};
  }
};

// Stage 0: B's vertices placed by tb, into the thread's buffer; false if any is not finite.
bool place(const ConvexPolyhedron& b, const Transform& tb, std::vector<Vec3>& wb) {
  wb.resize(b.vertices().size());
  for (std::size_t i = 0; i < wb.size(); ++i)
    wb[i] = tb.apply(b.vertices()[i]);
  return std::all_of(wb.begin(), wb.end(), [](Vec3 p) { return is_finite(p); });
}

// Stage 1, containment first, as MeshPairDistance: a vertex of one strictly inside the other
// solid (one component each) makes the distance 0, the solids overlapping or nested.
bool nested(const PlacedPair& pair, PairDistance3& out) {
  const Vec3 va0 = pair.a.vertices()[0];
  if (inside::point_in_convex(pair.a, pair.wb[0]) == Location::inside) {
    out.contact = inside::PairWitness::vertex_of_b_in_a;
    out.vertex = 0;
    out.point_a = out.point_b = pair.wb[0];
    return true;
  }
  if (inside::point_in_convex(pair.b, pair.wb, va0) == Location::inside) {
    out.contact = inside::PairWitness::vertex_of_a_in_b;
    out.vertex = 0;
    out.point_a = out.point_b = va0;
    return true;
  }
  return false;
}

// The faces around every vertex equal to p (placed vertices may coincide after rounding).
void faces_around(const ConvexPolyhedron& c, std::span<const Vec3> vertices, Vec3 p,
                  std::vector<std::int32_t>& faces) {
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    if (!(vertices[k] == p)) continue;
    const std::span<const std::int32_t> around = c.faces_around(static_cast<std::int32_t>(k));
    faces.insert(faces.end(), around.begin(), around.end());
  }
}

// Stage 2: a proven upper bound of the surfaces' distance, the least over the pairs of faces
// around GJK's closest simplices (one of them holds the closest pair when GJK has converged).
double upper_bound(const PlacedPair& pair, const bound::GjkResult& g) {
  thread_local std::vector<std::int32_t> near_a, near_b;
  near_a.clear();
  near_b.clear();
  for (int i = 0; i < g.simplex_size; ++i) {
    faces_around(pair.a, pair.a.vertices(), g.simplex_a[static_cast<std::size_t>(i)], near_a);
    faces_around(pair.b, pair.wb, g.simplex_b[static_cast<std::size_t>(i)], near_b);
  }
  double upper = kInf;
  for (const std::int32_t fa : near_a) {
    for (const std::int32_t fb : near_b) {
      double lo = 0, hi = 0;
      detail::triangle_pair_bounds(pair.face_a(fa), pair.face_b(fb), pair.slack, lo, hi);
      upper = std::min(upper, hi);
    }
  }
  return upper;
}

// Stage 3: the faces GJK's direction cannot rule out. A face f of A is at least its separation
// along w = v from B's farthest vertex away (rounding bounded), so it is out when that exceeds
// the upper bound; likewise for B's faces against A.
void faces_left(const PlacedPair& pair, const bound::GjkResult& g, double upper,
                std::vector<std::int32_t>& keep_a, std::vector<std::int32_t>& keep_b) {
  keep_a.clear();
  keep_b.clear();
  const Vec3 w = g.v, y = g.point_b;
  const double ww = dot(w, w);
  const bool directed = !g.origin_inside && ww > 0 && std::isfinite(ww) && upper < kInf;
  double a_min = kInf, b_max = -kInf;
  if (directed) {
    for (const Vec3& p : pair.a.vertices())
      a_min = std::min(a_min, detail::separation_bound(p, y, w, 1.0));
    for (const Vec3& p : pair.wb)
      b_max = std::max(b_max, detail::separation_bound(p, y, w, -1.0));
  }
  const auto count_a = static_cast<std::int32_t>(pair.a.face_indices().size());
  for (std::int32_t f = 0; f < count_a; ++f) {
    if (directed) {
      const Triangle3 t = pair.face_a(f);
      const double lo = std::min({detail::separation_bound(t.a, y, w, 1.0),
                                  detail::separation_bound(t.b, y, w, 1.0),
                                  detail::separation_bound(t.c, y, w, 1.0)});
      if (detail::squared_separation_lower(lo - b_max, ww) > upper) continue;
    }
    keep_a.push_back(f);
  }
  const auto count_b = static_cast<std::int32_t>(pair.b.face_indices().size());
  for (std::int32_t f = 0; f < count_b; ++f) {
    if (directed) {
      const Triangle3 t = pair.face_b(f);
      const double hi = std::max({detail::separation_bound(t.a, y, w, -1.0),
                                  detail::separation_bound(t.b, y, w, -1.0),
                                  detail::separation_bound(t.c, y, w, -1.0)});
      if (detail::squared_separation_lower(a_min - hi, ww) > upper) continue;
    }
    keep_b.push_back(f);
  }
}

// Stages 2 and 3 after GJK's guess (a direction v from B to A and the simplices of its closest
// points): the faces left for the pairs' stage and the upper bound they start from.
struct Narrowed {
  std::vector<std::int32_t> keep_a, keep_b;
  double upper = kInf;
};

void narrow(const PlacedPair& pair, Narrowed& left) {
  const bound::GjkResult g = bound::gjk(
      [&](Vec3 d) { return pair.a.support(d); },
      [&](Vec3 d) { return pair.wb[static_cast<std::size_t>(support_index(pair.wb, d))]; });
  left.upper = upper_bound(pair, g);
  faces_left(pair, g, left.upper, left.keep_a, left.keep_b);
}

// One thread's buffers of the pair stages, kept between queries.
struct PairBuffers {
  std::vector<Vec3> wb;
  Narrowed left;
  std::vector<detail::PairContender> contenders;
};

// Stages 0 to 3: B placed, containment, GJK's narrowing. `narrowed` when the faces left are
// to be paired; otherwise the answer is known (`out` set for `nested`).
enum class Opening { not_finite, nested, narrowed };
struct Opened {
  Opening state;
  PlacedPair pair;
};

Opened open_pair(const ConvexPolyhedron& a, double a_max_abs, const ConvexPolyhedron& b,
                 const Transform& tb, PairBuffers& buffers, PairDistance3& out) {
  const bool finite = place(b, tb, buffers.wb);
  const PlacedPair pair{a, b, buffers.wb,
                        detail::triangle_slack(std::max(a_max_abs, max_abs(buffers.wb)))};
  if (!finite) return {Opening::not_finite, pair};
  if (nested(pair, out)) return {Opening::nested, pair};
  narrow(pair, buffers.left);
  return {Opening::narrowed, pair};
}

// Stage 4: the pairs of the faces left, bounded; those that can be closest are kept, in (a, b)
// order. Returns true, early, when a pair is proven within `proven` (squared; -infinity: never).
bool collect_contenders(const PlacedPair& pair, const Narrowed& left, double proven,
                        PairDistance3& out, std::vector<detail::PairContender>& contenders) {
  contenders.clear();
  double best = left.upper;
  for (const std::int32_t fa : left.keep_a) {
    const Triangle3 ta = pair.face_a(fa);
    for (const std::int32_t fb : left.keep_b) {
      double lo = 0, hi = 0;
      detail::triangle_pair_bounds(ta, pair.face_b(fb), pair.slack, lo, hi);
      ++out.node_pairs;
      if (lo > best) continue;
      if (hi <= proven) return true;  // no need to know which pair is closest
      contenders.push_back({fa, fb, lo, hi});
      best = std::min(best, hi);
    }
  }
  std::erase_if(contenders, [&](const detail::PairContender& c) { return c.lo > best; });
  out.contenders = contenders.size();
  return false;
}

// Stage 5: the exact stage among the contenders, in the order of the distance-tie rule, as the
// mesh and region pairs take it (least_contender.h). Stage 4 has already dropped the pairs its
// best bound rules out, so no bound is passed (infinity drops nothing), and its (a, b) order is
// the one least_contender sorts into: the same winner as a walk in collection order.
predicates::FlatPair3 closest_contender(const PlacedPair& pair,
                                        std::vector<detail::PairContender>& contenders,
                                        PairDistance3& out) {
  const detail::LeastContender<predicates::FlatPair3> winner =
      detail::least_contender(contenders, kInf, [&](std::int32_t a, std::int32_t b) {
        return predicates::closest_flats(pair.face_a(a), pair.face_b(b));
      });
  if (winner.found) {
    out.triangle_a = winner.a;
    out.triangle_b = winner.b;
  }
  return winner.pair;
}

}  // namespace

Result<ConvexDistance> ConvexDistance::prepare(const ConvexPolyhedron& polyhedron) {
  if (polyhedron.faces().empty()) {
    return Error{ErrorKind::unsupported,
                 "a convex polyhedron given by planes has no faces to measure to: build it from "
                 "a mesh"};
  }
  ConvexDistance out;
  out.polyhedron_ = polyhedron;
  Mesh surface;
  surface.vertices = polyhedron.vertices();
  surface.triangles = polyhedron.face_indices();
  out.surface_ = MeshDistance(surface, {.signs = false});
  out.max_abs_ = max_abs(polyhedron.vertices());
  return out;
}

Closest3 ConvexDistance::distance(Vec3 p, const PointQuery& query) const {
  Closest3 out =
      surface_.distance(p, {.signed_distance = false, .closest_point = query.closest_point});
  if (query.signed_distance && std::isfinite(out.distance))
    detail::apply_sign(out, inside::point_in_convex(polyhedron_, p));
  return out;
}

void ConvexDistance::distance(std::span<const Vec3> points, std::span<Closest3> out,
                              const PointQuery& query, const BatchOptions& options) const {
  const std::size_t n = batch_size(points.size(), out.size());
  surface_.distance(points.first(n), out.first(n),
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

Result<Closest3> point_convex(const ConvexPolyhedron& polyhedron, Vec3 p, const PointQuery& query) {
  auto prepared = ConvexDistance::prepare(polyhedron);
  if (!prepared) return prepared.error();
  return prepared->distance(p, query);
}

// The pair stages composed for the distance: every face pair that can be closest reaches the
// exact stage.
PairDistance3 convex_convex(const ConvexDistance& a, const ConvexDistance& b,
                            const Transform& transform_b) {
  PairDistance3 out;
  thread_local PairBuffers buffers;
  const auto [state, pair] =
      open_pair(a.polyhedron_, a.max_abs_, b.polyhedron_, transform_b, buffers, out);
  if (state == Opening::not_finite) out.distance = std::numeric_limits<double>::quiet_NaN();
  if (state != Opening::narrowed) return out;
  (void)collect_contenders(pair, buffers.left, -kInf, out, buffers.contenders);
  const predicates::FlatPair3 winner = closest_contender(pair, buffers.contenders, out);
  out.contact =
      predicates::flats_meet(winner) ? inside::PairWitness::triangles : inside::PairWitness::none;
  out.distance = predicates::rounded_distance(winner);
  const predicates::ClosestPoints3 points = predicates::rounded_closest_points(winner);
  out.point_a = points.a;
  out.point_b = points.b;
  return out;
}

// The same stages composed for "distance <= d": a pair proven within d ends the search, and the
// exact stage compares the winner with d, not rounding it.
bool convex_convex_within(const ConvexDistance& a, const ConvexDistance& b,
                          const Transform& transform_b, double d) {
  if (!(d >= 0)) return false;
  PairDistance3 out;
  thread_local PairBuffers buffers;
  const auto [state, pair] =
      open_pair(a.polyhedron_, a.max_abs_, b.polyhedron_, transform_b, buffers, out);
  if (state != Opening::narrowed) return state == Opening::nested;
  const double proven = detail::squared_bounds(d).lo;
  if (collect_contenders(pair, buffers.left, proven, out, buffers.contenders)) return true;
  const predicates::FlatPair3 winner = closest_contender(pair, buffers.contenders, out);
  return predicates::flats_meet(winner) ||
         predicates::compare_squared_distance(winner, d) != Sign::positive;
}

}  // namespace contain::distance
