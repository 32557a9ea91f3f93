#include "contain/distance/mesh_pair_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/bvh/triangle_boxes.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"
#include "distance/flat_answer.h"
#include "distance/oriented_box.h"
#include "distance/search_tree.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

constexpr double kEps = predicates::unit_roundoff<double>;
constexpr double kInf = std::numeric_limits<double>::infinity();

double max_abs(const Mesh& mesh) {
  double m = 0.0;
  for (const Vec3& v : mesh.vertices)
    m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return m;
}

Mesh placed_mesh(const Mesh& mesh, const Transform& transform) {
  Mesh out = mesh;
  for (Vec3& v : out.vertices)
    v = transform.apply(v);
  return out;
}

Triangle3 triangle_of(const std::vector<Vec3>& v, const TriangleIndices& t) {
  return {v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
          v[static_cast<std::size_t>(t[2])]};
}

// The gap of two intervals along one axis (0 when they overlap); plain comparisons, so that the
// whole bound inlines into the descent's inner loop.
inline double axis_gap(double a_min, double a_max, double b_min, double b_max) {
  const double g1 = a_min - b_max, g2 = b_min - a_max;
  const double g = g1 > g2 ? g1 : g2;
  return g > 0 ? g : 0.0;
}

inline double box_box_lower_bound(const Box3& a, const Box3& b) {
  const double dx = axis_gap(a.min.x, a.max.x, b.min.x, b.max.x);
  const double dy = axis_gap(a.min.y, a.max.y, b.min.y, b.max.y);
  const double dz = axis_gap(a.min.z, a.max.z, b.min.z, b.max.z);
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

// B's node box placed by `tb`, from the local box: an interval product per coordinate,
// widened so that it holds every vertex of the box as tb.apply computes it. Both that and this
// computation are sums of four terms (three products and t_i): each within gamma_4 < 4.01 eps
// of s_i = sum_j |r_ij| max(|lo_j|, |hi_j|) + |t_i| from the exact value; the widening and s_i's
// own rounding fit in 10 eps; 16 denorm_min cover underflowed products. O(1) per node instead
// of refitting B's hierarchy to every pose: only the nodes the descent meets are placed.
Box3 placed_box(const Box3& local, const Transform& tb) {
  const double lo[3] = {local.min.x, local.min.y, local.min.z};
  const double hi[3] = {local.max.x, local.max.y, local.max.z};
  const double t[3] = {tb.t.x, tb.t.y, tb.t.z};
  double mn[3], mx[3];
  for (int i = 0; i < 3; ++i) {
    double a = t[i], b = t[i], s = std::fabs(t[i]);
    for (int j = 0; j < 3; ++j) {
      const double r = tb.r[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      const double p = r * lo[j], q = r * hi[j];
      a += std::min(p, q);
      b += std::max(p, q);
      s += std::fabs(r) * std::max(std::fabs(lo[j]), std::fabs(hi[j]));
    }
    const double pad = 10 * kEps * s + 16 * std::numeric_limits<double>::denorm_min();
    mn[i] = a - pad;
    mx[i] = b + pad;
  }
  return {{mn[0], mn[1], mn[2]}, {mx[0], mx[1], mx[2]}};
}

Box3 triangle_box(const Triangle3& t) {
  Box3 box;
  box.expand(t.a);
  box.expand(t.b);
  box.expand(t.c);
  return box;
}

// Leaves of up to this many triangles have their placed triangles gathered once per leaf pair.
constexpr std::int32_t kMaxLeaf = 8;

// B's vertices as placed by one pose, each computed by Transform::apply on first use (a stamp
// per vertex): the descent meets a few thousand of B's vertices, and placing all of them cost
// 0.2 ms per pose on the 100k-triangle bench, a fifth of FCL's whole query.
class PlacedVertices {
 public:
  void reset(const std::vector<Vec3>& local, const Transform& tb) {
    local_ = &local;
    tb_ = tb;
    if (stamp_.size() < local.size() || ++current_ == 0) {
      stamp_.assign(std::max(stamp_.size(), local.size()), 0);
      placed_.resize(stamp_.size());
      current_ = 1;
    }
  }
  Vec3 operator[](std::int32_t v) {
    const auto u = static_cast<std::size_t>(v);
    if (stamp_[u] != current_) {
      stamp_[u] = current_;
      placed_[u] = tb_.apply((*local_)[u]);
    }
    return placed_[u];
  }
  Triangle3 triangle(const TriangleIndices& t) {
    return {(*this)[t[0]], (*this)[t[1]], (*this)[t[2]]};
  }

 private:
  const std::vector<Vec3>* local_ = nullptr;
  Transform tb_;
  std::vector<Vec3> placed_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
};

// A bound on every coordinate of B's vertices as placed by tb (Transform::apply), B's local
// coordinates at most m in magnitude: |t_i| + sum_j |r_ij| m, within gamma_4 of its own
// rounding and of the computed coordinates' error: times (1 + 16 eps).
double placed_max_abs(const Transform& tb, double m) {
  double out = 0;
  const double t[3] = {tb.t.x, tb.t.y, tb.t.z};
  for (std::size_t i = 0; i < 3; ++i)
    out = std::max(
        out, std::fabs(t[i]) +
                 ((std::fabs(tb.r[i][0]) + std::fabs(tb.r[i][1])) + std::fabs(tb.r[i][2])) * m);
  return out * (1 + 16 * kEps);
}

struct PairContender {
  std::int32_t a, b;
  double lo, hi;
};

}  // namespace

struct MeshPairDistance::Volumes {
  std::vector<detail::OrientedBox> a, b;
  double extent_a = 0, extent_b = 0;
  std::vector<std::int32_t> min_a, min_b;  // the lowest triangle under each node
};

namespace {

// The lowest item under each node of `bvh` (children come after their parent).
std::vector<std::int32_t> least_items(const bvh::Bvh& bvh) {
  const std::span<const bvh::Node> nodes = bvh.nodes();
  const std::span<const std::int32_t> items = bvh.items();
  std::vector<std::int32_t> out(nodes.size());
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const bvh::Node& n = nodes[k];
    if (n.is_leaf()) {
      out[k] = *std::min_element(items.begin() + n.first, items.begin() + n.first + n.count);
    } else {
      out[k] = std::min(out[k + 1], out[static_cast<std::size_t>(n.first)]);
    }
  }
  return out;
}

}  // namespace

const char* to_string(PairContact contact) {
  switch (contact) {
    case PairContact::touching:
      return "touching";
    case PairContact::vertex_of_a_in_b:
      return "vertex_of_a_in_b";
    case PairContact::vertex_of_b_in_a:
      return "vertex_of_b_in_a";
    case PairContact::separate:
      break;
  }
  return "separate";
}

MeshPairDistance::MeshPairDistance(const Mesh& a, const Mesh& b,
                                   const MeshPairDistanceOptions& options)
    : a_world_(placed_mesh(a, options.transform_a)), b_(b) {
  bvh_a_ = bvh::Bvh(bvh::triangle_boxes(a_world_), options.bvh);
  bvh_b_ = bvh::Bvh(bvh::triangle_boxes(b_), options.bvh);
  if (!a_world_.triangles.empty()) {
    index_a_ = inside::MeshIndex(a_world_, options.index);
    a_solid_ = index_a_.regime() == inside::MeshRegime::closed_exact;
  }
  b_solid_ = !b_.triangles.empty() && validate_mesh(b_).closed();
  a_components_ = component_vertices(a_world_);
  b_components_ = component_vertices(b_);
  auto volumes = std::make_shared<Volumes>();
  volumes->a = detail::oriented_boxes(bvh_a_, a_world_);
  volumes->b = detail::oriented_boxes(bvh_b_, b_);
  volumes->extent_a = detail::oriented_extent(volumes->a);
  volumes->extent_b = detail::oriented_extent(volumes->b);
  volumes->min_a = least_items(bvh_a_);
  volumes->min_b = least_items(bvh_b_);
  volumes_ = std::move(volumes);
  a_max_abs_ = max_abs(a_world_);
  b_max_abs_ = max_abs(b_);
}

PairDistance3 MeshPairDistance::distance(const Transform& transform_b) const {
  return query(transform_b, 0.0, nullptr);
}

bool MeshPairDistance::within(const Transform& transform_b, double d) const {
  if (!(d >= 0)) return false;
  bool answer = false;
  (void)query(transform_b, d, &answer);
  return answer;
}

PairDistance3 MeshPairDistance::query(const Transform& tb, double within_d,
                                      bool* within_out) const {
  PairDistance3 out;
  if (bvh_a_.empty() || bvh_b_.empty()) {
    out.distance = kInf;
    return out;
  }
  // B's vertices as placed: the doubles every decision is exact on.
  thread_local PlacedVertices wb;
  wb.reset(b_.vertices, tb);
  const double slack = detail::triangle_slack(std::max(a_max_abs_, placed_max_abs(tb, b_max_abs_)));
  // 1. Overlap first: a vertex of one inside the other solid makes the distance 0 whatever the
  // surfaces do (and settles nested solids, whose surfaces may be far apart, at once).
  if (a_solid_) {
    for (const std::int32_t v : b_components_) {
      if (index_a_.locate(wb[v]) == Location::inside) {
        out.contact = PairContact::vertex_of_b_in_a;
        out.vertex = v;
        out.point_a = out.point_b = wb[v];
        out.distance = 0.0;
        if (within_out) *within_out = true;
        return out;
      }
    }
  }
  if (b_solid_) {
    for (const std::int32_t v : a_components_) {
      const Vec3 q = a_world_.vertices[static_cast<std::size_t>(v)];
      bool odd = false;
      bool on_surface = false;
      // The perturbed ray along +x against B as placed, culled by B's placed boxes; a vertex on
      // B's surface is a touching pair, which the descent finds.
      (void)bvh_b_.traverse(
          [&](const bvh::Node& node, std::int32_t index) {
            (void)index;
            const Box3 w = placed_box(node.box, tb);
            return w.max.x >= q.x && w.min.y <= q.y && q.y <= w.max.y && w.min.z <= q.z &&
                   q.z <= w.max.z;
          },
          [&](std::int32_t t) {
            const Triangle3 tri = wb.triangle(b_.triangles[static_cast<std::size_t>(t)]);
            if (predicates::closest_feature(q, tri) == predicates::TriangleFeature::face &&
                predicates::orient3d(tri.a, tri.b, tri.c, q) == Sign::zero) {
              on_surface = true;
            }
            if (predicates::perturbed_ray_crosses(tri.a, tri.b, tri.c, q)) odd = !odd;
            return bvh::Visit::proceed;
          });
      if (odd && !on_surface) {
        out.contact = PairContact::vertex_of_a_in_b;
        out.vertex = v;
        out.point_a = out.point_b = q;
        out.distance = 0.0;
        if (within_out) *within_out = true;
        return out;
      }
    }
  }

  // 2. The descent: pairs of nodes, nearer first, pruned against the best upper bound. Node
  // pairs are bounded by their oriented boxes (oriented_box.h: a separating axis along the line
  // between the centres, with a proven rounding margin); leaf pairs then by the exact boxes of
  // B's placed leaf triangles and the triangles' own bounds.
  const std::span<const bvh::Node> na = bvh_a_.nodes(), nb = bvh_b_.nodes();
  const std::span<const std::int32_t> ia = bvh_a_.items(), ib = bvh_b_.items();
  const std::span<const detail::OrientedBox> oa = volumes_->a, ob = volumes_->b;
  const detail::OrientedPose pose =
      detail::oriented_pose(tb, volumes_->extent_a, volumes_->extent_b);
  // Per node of B, computed once per query (a stamp per node): the centre of its oriented box
  // as placed (any point serves as the bound's direction), and for leaves the exact box of the
  // placed triangles.
  thread_local std::vector<Vec3> centre_cache;
  thread_local std::vector<Box3> box_cache;
  thread_local std::vector<std::uint32_t> centre_stamp, box_stamp;
  thread_local std::uint32_t stamp = 0;
  if (box_stamp.size() < nb.size() || ++stamp == 0) {
    box_stamp.assign(std::max(box_stamp.size(), nb.size()), 0);
    centre_stamp.assign(box_stamp.size(), 0);
    box_cache.resize(box_stamp.size());
    centre_cache.resize(box_stamp.size());
    stamp = 1;
  }
  const auto box_b = [&](std::int32_t k) -> const Box3& {
    const auto u = static_cast<std::size_t>(k);
    if (box_stamp[u] != stamp) {
      const bvh::Node& node = nb[u];
      Box3 box;
      for (std::int32_t i = node.first; i < node.first + node.count; ++i)
        for (const std::int32_t v :
             b_.triangles[static_cast<std::size_t>(ib[static_cast<std::size_t>(i)])])
          box.expand(wb[v]);
      box_stamp[u] = stamp;
      box_cache[u] = box;
    }
    return box_cache[u];
  };
  const auto centre_b = [&](std::int32_t k) -> Vec3 {
    const auto u = static_cast<std::size_t>(k);
    if (centre_stamp[u] != stamp) {
      centre_stamp[u] = stamp;
      centre_cache[u] = tb.apply(ob[u].c);
    }
    return centre_cache[u];
  };
  const auto lower = [&](std::int32_t a, std::int32_t b) {
    return detail::oriented_box_lower(oa[static_cast<std::size_t>(a)],
                                      ob[static_cast<std::size_t>(b)], centre_b(b), pose);
  };
  // The size that decides which node to split: the oriented box's surface area (over 8).
  const auto size = [](const detail::OrientedBox& o) {
    return o.h[0] * o.h[1] + o.h[1] * o.h[2] + o.h[2] * o.h[0];
  };
  struct Entry {
    std::int32_t a, b;
    double lb;
  };
  thread_local std::vector<Entry> stack;
  thread_local std::vector<PairContender> contenders;
  stack.clear();
  contenders.clear();
  double best = kInf;
  // Depth first, the nearer child pair first (pushed last), so that the first leaf pairs reached
  // are near the closest ones and the upper bound falls fast. A best-first heap visits fewer
  // pairs (22k against 35k per pose on the armadillo bench, with axis-aligned boxes) but its
  // upkeep costs more than they save (4.6 against 3.4 ms per pose).
  // Touching: once a triangle pair is found to meet (exactly), the distance is 0 and the answer
  // is the lowest meeting pair (distance-tie rule: lowest triangle of A, then of B). From then
  // on best = 0 prunes every pair that surely does not meet, and a pair of nodes whose lowest
  // triangles (mins_a, mins_b) come at or after the pair found holds no lower pair.
  bool meet = false;
  std::int32_t meet_a = 0, meet_b = 0;
  const std::span<const std::int32_t> mins_a = volumes_->min_a, mins_b = volumes_->min_b;
  const auto at_or_after = [&](std::int32_t ta, std::int32_t tbi) {
    return ta > meet_a || (ta == meet_a && tbi >= meet_b);
  };
  auto push = [&](const Entry& e) {
    if (e.lb > best) return;
    if (meet &&
        at_or_after(mins_a[static_cast<std::size_t>(e.a)], mins_b[static_cast<std::size_t>(e.b)]))
      return;
    stack.push_back(e);
  };
  push({0, 0, lower(0, 0)});
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    if (e.lb > best) continue;  // best fell since it was pushed
    if (meet &&
        at_or_after(mins_a[static_cast<std::size_t>(e.a)], mins_b[static_cast<std::size_t>(e.b)]))
      continue;
    ++out.node_pairs;
    const bvh::Node& p = na[static_cast<std::size_t>(e.a)];
    const bvh::Node& q = nb[static_cast<std::size_t>(e.b)];
    if (p.is_leaf() && q.is_leaf()) {
      // The triangles' own boxes first: a box gap beyond the best bound rules a pair out for a
      // few comparisons, before the 15 closest-point computations of its bounds.
      Triangle3 tris_b[kMaxLeaf];
      Box3 boxes_b[kMaxLeaf];
      const std::int32_t count_b = std::min<std::int32_t>(q.count, kMaxLeaf);
      const Box3& leaf_box_b = box_b(e.b);
      for (std::int32_t t = 0; t < count_b; ++t) {
        const std::int32_t tbi = ib[static_cast<std::size_t>(q.first + t)];
        tris_b[t] = wb.triangle(b_.triangles[static_cast<std::size_t>(tbi)]);
        boxes_b[t] = triangle_box(tris_b[t]);
      }
      Triangle3 tris_a[kMaxLeaf];
      const std::int32_t count_a = std::min<std::int32_t>(p.count, kMaxLeaf);
      for (std::int32_t s = 0; s < count_a; ++s)
        tris_a[s] = triangle_of(a_world_.vertices, a_world_.triangles[static_cast<std::size_t>(
                                                       ia[static_cast<std::size_t>(p.first + s)])]);
      // The two leaves' corners along the line between the boxes' centres: boxes near each other
      // often hold patches that face apart (most leaf pairs end here).
      if (count_a == p.count && count_b == q.count) {
        const Vec3 w = (p.box.min + p.box.max) - (leaf_box_b.min + leaf_box_b.max);
        if (detail::triangle_sets_quick_lower(std::span<const Triangle3>(tris_a, count_a),
                                              std::span<const Triangle3>(tris_b, count_b),
                                              w) > best)
          continue;
      }
      for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
        const std::int32_t ta = ia[static_cast<std::size_t>(s)];
        const Triangle3 tri_a =
            s - p.first < count_a
                ? tris_a[s - p.first]
                : triangle_of(a_world_.vertices, a_world_.triangles[static_cast<std::size_t>(ta)]);
        const Box3 box_a = triangle_box(tri_a);
        if (box_box_lower_bound(box_a, leaf_box_b) > best) continue;
        for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
          const std::int32_t tbi = ib[static_cast<std::size_t>(t)];
          const std::int32_t k = t - q.first;
          if (meet && at_or_after(ta, tbi)) continue;
          Triangle3 tri_b;
          if (k < count_b) {
            if (box_box_lower_bound(box_a, boxes_b[k]) > best) continue;
            tri_b = tris_b[k];
          } else {
            tri_b = wb.triangle(b_.triangles[static_cast<std::size_t>(tbi)]);
          }
          if (detail::triangle_pair_quick_lower(tri_a, tri_b) > best) continue;
          double lo = 0, hi = 0;
          detail::triangle_pair_bounds(tri_a, tri_b, slack, lo, hi);
          if (lo > best) continue;
          if (lo == 0 && predicates::flats_meet(predicates::closest_flats(tri_a, tri_b))) {
            if (within_out != nullptr) {  // distance 0: within any d >= 0
              *within_out = true;
              return out;
            }
            meet = true;
            meet_a = ta;
            meet_b = tbi;
            best = 0;
            continue;
          }
          if (meet) continue;  // not meeting: not an answer any more
          contenders.push_back({ta, tbi, lo, hi});
          best = std::min(best, hi);
        }
      }
      continue;
    }
    const bool split_a =
        q.is_leaf() || (!p.is_leaf() && size(oa[static_cast<std::size_t>(e.a)]) >=
                                            size(ob[static_cast<std::size_t>(e.b)]));
    Entry c1 = e, c2 = e;
    if (split_a) {
      c1.a = e.a + 1;
      c2.a = p.first;
    } else {
      c1.b = e.b + 1;
      c2.b = q.first;
    }
    c1.lb = lower(c1.a, c1.b);
    c2.lb = lower(c2.a, c2.b);
    // The nearer pair on top; of two at the same bound (two pairs that may touch) the one with
    // the lower triangles, which finds the lowest meeting pair sooner.
    if (c1.lb < c2.lb || (c1.lb == c2.lb && (split_a ? mins_a[static_cast<std::size_t>(c1.a)] <
                                                           mins_a[static_cast<std::size_t>(c2.a)]
                                                     : mins_b[static_cast<std::size_t>(c1.b)] <
                                                           mins_b[static_cast<std::size_t>(c2.b)])))
      std::swap(c1, c2);
    push(c1);
    push(c2);
  }
  if (meet) {  // the lowest meeting pair is the answer; the other contenders are farther
    contenders.clear();
    contenders.push_back({meet_a, meet_b, 0, 0});
  }
  std::erase_if(contenders, [&](const PairContender& c) { return c.lo > best; });
  out.contenders = contenders.size();

  // 3. The exact stage: the least exact distance among the contenders, ties to the lowest
  // triangle of A, then of B.
  std::sort(contenders.begin(), contenders.end(),
            [](const PairContender& x, const PairContender& y) {
              return x.a != y.a ? x.a < y.a : x.b < y.b;
            });
  predicates::FlatPair3 winner{};
  bool have = false;
  for (const PairContender& c : contenders) {
    const predicates::FlatPair3 pair = predicates::closest_flats(
        triangle_of(a_world_.vertices, a_world_.triangles[static_cast<std::size_t>(c.a)]),
        wb.triangle(b_.triangles[static_cast<std::size_t>(c.b)]));
    if (!have || predicates::compare_squared_distances(pair, winner) == Sign::negative) {
      winner = pair;
      out.triangle_a = c.a;
      out.triangle_b = c.b;
      have = true;
    }
  }
  const bool touching = predicates::flats_meet(winner);
  if (within_out != nullptr && !touching &&
      predicates::compare_squared_distance(winner, within_d) != Sign::positive) {
    *within_out = true;
    return out;
  }

  if (within_out) {
    *within_out = touching;
    return out;
  }
  out.contact = touching ? PairContact::touching : PairContact::separate;
  out.distance = predicates::rounded_distance(winner);
  const predicates::ClosestPoints3 points = predicates::rounded_closest_points(winner);
  out.point_a = points.a;
  out.point_b = points.b;
  return out;
}

void MeshPairDistance::distance(std::span<const Transform> poses, std::span<PairDistance3> out,
                                const BatchOptions& options) const {
  const std::size_t n = std::min(poses.size(), out.size());
  // Poses are heavy items: one is enough for a thread.
  parallel_for(n, options, std::size_t{1}, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = distance(poses[i]);
  });
}

void MeshPairDistance::within(std::span<const Transform> poses, double d,
                              std::span<std::uint8_t> out, const BatchOptions& options) const {
  const std::size_t n = std::min(poses.size(), out.size());
  parallel_for(n, options, std::size_t{1}, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = within(poses[i], d) ? 1 : 0;
  });
}

PairDistance3 mesh_mesh(const Mesh& a, const Mesh& b, const Transform& transform_a,
                        const Transform& transform_b) {
  return MeshPairDistance(a, b, {.transform_a = transform_a}).distance(transform_b);
}

}  // namespace contain::distance
