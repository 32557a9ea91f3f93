#include "contain/distance/mesh_distance.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "contain/predicates/closest_feature.h"
#include "contain/predicates/cross_dot.h"
#include "contain/predicates/squared_distance.h"
#include "distance/flat_answer.h"
#include "distance/morton_order.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

using predicates::Flat3;
using predicates::FlatPair3;

void add(MeshDistanceStats& total, const MeshDistanceStats& part) {
  total.queries += part.queries;
  total.nodes += part.nodes;
  total.triangles += part.triangles;
  total.cheap += part.cheap;
  total.contenders += part.contenders;
  total.exact_comparisons += part.exact_comparisons;
  total.shared_features += part.shared_features;
}

std::vector<Triangle3> triangles_of(const Mesh& mesh) {
  std::vector<Triangle3> out;
  out.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    out.push_back(mesh.triangle(t));
  return out;
}

struct PointWinner {
  std::int32_t triangle = -1;
  predicates::TriangleFeature feature{};
  FlatPair3 pair{};
};

// The corner of t at exactly v, or -1.
int corner_at(const Triangle3& t, Vec3 v) {
  for (int k = 0; k < 3; ++k)
    if (t.corner(k) == v) return k;
  return -1;
}

// Is t proven no nearer to p than the winner's feature (so that it can neither win nor, coming
// later in index order, take a tie)? Only where t shares that feature, by one or two exact
// predicates in place of t's whole closest-feature decision (the fan around a closest vertex, the
// two faces along a closest edge: most contenders of a far point):
// - a vertex v of t is a closest point of t iff no edge of t leads from v towards p,
//   dot_sign(v, u, p) <= 0 for both other corners u (t is the hull of its corners; degenerate
//   triangles too);
// - where the winner's closest point q is inside the edge (v, w) (its feature is that edge) and t
//   has the edge with third corner x, q is closest in t iff (p - q) . (x - q) <= 0, and with
//   p - q perpendicular to the edge that is the sign of ((w - v) x (p - v)) . ((w - v) x (x - v))
//   (Binet-Cauchy), i.e. cross_dot(v, w, p, x) <= 0.
bool no_nearer(Vec3 p, const Triangle3& t, const Triangle3& won, predicates::TriangleFeature f) {
  using predicates::TriangleFeature;
  const int fi = static_cast<int>(f);
  if (f <= TriangleFeature::vertex_c) {
    const Vec3 v = won.corner(fi);
    const int k = corner_at(t, v);
    if (k < 0) return false;
    return predicates::dot_sign(v, t.corner((k + 1) % 3), p) != Sign::positive &&
           predicates::dot_sign(v, t.corner((k + 2) % 3), p) != Sign::positive;
  }
  if (f == TriangleFeature::face) return false;
  const int e = fi - static_cast<int>(TriangleFeature::edge_ab);
  const Vec3 v = won.corner(e), w = won.corner((e + 1) % 3);
  const int kv = corner_at(t, v), kw = corner_at(t, w);
  if (kv < 0 || kw < 0 || kv == kw) return false;
  const Vec3 x = t.corner(3 - kv - kw);
  return predicates::cross_dot(v, w, p, x) != Sign::positive;
}

// The exact stage: among the contenders, the triangle of least exact distance, ties to the
// lowest index (distance-tie rule). Each contender's closest feature is decided exactly; equal
// features need no comparison.
PointWinner resolve_point(Vec3 p, const detail::TriangleSearch& search,
                          std::vector<detail::Contender>& contenders, MeshDistanceStats& work) {
  // Lowest index first, so that a tie keeps the first one met.
  std::sort(contenders.begin(), contenders.end(),
            [](const detail::Contender& a, const detail::Contender& b) { return a.item < b.item; });
  PointWinner best;
  for (const detail::Contender& c : contenders) {
    const Triangle3& t = search.triangle(c.item);
    if (best.triangle >= 0 && no_nearer(p, t, search.triangle(best.triangle), best.feature)) {
      ++work.shared_features;
      continue;
    }
    const predicates::TriangleFeature feature = predicates::closest_feature(t, p);
    const Flat3 flat = predicates::feature_flat(t, feature);
    const FlatPair3 pair{predicates::point_flat(p), flat};
    if (best.triangle < 0) {
      best = {c.item, feature, pair};
      continue;
    }
    if (predicates::same_flat(flat, best.pair.b)) continue;
    ++work.exact_comparisons;
    if (predicates::compare_squared_distances(pair, best.pair) == Sign::negative) {
      best = {c.item, feature, pair};
    }
  }
  return best;
}

}  // namespace

MeshDistance::MeshDistance() : search_(std::make_unique<detail::TriangleSearch>()) {}

MeshDistance::MeshDistance(const Mesh& mesh, const MeshDistanceOptions& options)
    : search_(std::make_unique<detail::TriangleSearch>(triangles_of(mesh), options.bvh)),
      signs_(options.signs) {
  if (signs_) index_ = inside::MeshIndex(mesh, options.index);
}

MeshDistance::~MeshDistance() = default;
MeshDistance::MeshDistance(MeshDistance&&) noexcept = default;
MeshDistance& MeshDistance::operator=(MeshDistance&&) noexcept = default;

std::size_t MeshDistance::size() const {
  return search_->size();
}

Closest3 MeshDistance::distance(Vec3 p, const PointQuery& query) const {
  MeshDistanceStats unused;
  return query_with_hint(p, query, -1, unused);
}

Closest3 MeshDistance::query_with_hint(Vec3 p, const PointQuery& query, std::int32_t hint,
                                       MeshDistanceStats& work) const {
  ++work.queries;
  Closest3 out;
  if (!is_finite(p)) {
    out.distance = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  if (search_->empty()) {
    out.distance = std::numeric_limits<double>::infinity();
    return out;
  }
  // One buffer per thread: queries allocate nothing once it has grown.
  thread_local std::vector<detail::Contender> contenders;
  detail::SearchStats stats;
  search_->contenders(p, contenders, &stats, hint);
  work.nodes += stats.nodes;
  work.triangles += stats.items;
  work.cheap += stats.cheap;
  work.contenders += contenders.size();
  const PointWinner w = resolve_point(p, *search_, contenders, work);
  out = detail::answer(w.pair, query.closest_point);
  out.feature = w.triangle;
  if (query.signed_distance) {
    if (!signs_) {
      out.distance = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    detail::apply_sign(out, index_.locate(p));
  }
  return out;
}

void MeshDistance::distance(std::span<const Vec3> points, std::span<Closest3> out,
                            const PointQuery& q, const BatchOptions& options) const {
  static_cast<void>(distance_with_stats(points, out, q, options));
}

MeshDistanceStats MeshDistance::distance_with_stats(std::span<const Vec3> points,
                                                    std::span<Closest3> out, const PointQuery& q,
                                                    const BatchOptions& options) const {
  MeshDistanceStats total;
  std::mutex total_mutex;
  const std::size_t n = batch_size(points.size(), out.size());
  // Points in Morton order of their position, so that neighbours in the order are neighbours in
  // space and each query starts from the previous one's closest triangle (a hint: it bounds the
  // search early and never changes an answer, which is exact).
  const std::vector<std::uint32_t> order = detail::morton_order(points.first(n));
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    MeshDistanceStats work;
    std::int32_t hint = -1;
    for (std::size_t k = begin; k < end; ++k) {
      detail::prefetch_ahead<>(order, k, end, points.data(), out.data());
      const std::size_t i = order[k];
      out[i] = query_with_hint(points[i], q, hint, work);
      hint = out[i].feature;
    }
    const std::lock_guard lock(total_mutex);
    add(total, work);
  });
  return total;
}

bool MeshDistance::within(Vec3 p, double d) const {
  if (!(d >= 0) || !is_finite(p)) return false;
  if (search_->empty()) return false;
  const detail::SquaredBounds d2 = detail::squared_bounds(d);
  thread_local std::vector<detail::Contender> undecided;
  const int fast = search_->within(p, d2.lo, d2.hi, undecided);
  if (fast != 0) return fast > 0;
  for (const detail::Contender& c : undecided) {
    const Triangle3& t = search_->triangle(c.item);
    const FlatPair3 pair{predicates::point_flat(p),
                         predicates::feature_flat(t, predicates::closest_feature(t, p))};
    if (predicates::compare_squared_distance(pair, d) != Sign::positive) return true;
  }
  return false;
}

void MeshDistance::within(std::span<const Vec3> points, double d, std::span<std::uint8_t> out,
                          const BatchOptions& options) const {
  batch_map(points, out, options, 4096,
            [&](Vec3 p) -> std::uint8_t { return within(p, d) ? 1 : 0; });
}

Closest3 point_mesh(const Mesh& mesh, Vec3 p, const PointQuery& query) {
  MeshDistanceOptions options;
  options.signs = query.signed_distance;
  return MeshDistance(mesh, options).distance(p, query);
}

}  // namespace contain::distance
