#include "contain/distance/mesh_pair_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/bvh/nearest_pairs.h"
#include "contain/bvh/placed_box.h"
#include "contain/inside/placed_ray.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "contain/predicates/unit_roundoff.h"
#include "distance/bound_constants.h"
#include "distance/flat_answer.h"
#include "distance/least_contender.h"
#include "distance/oriented_box.h"
#include "distance/search_tree.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

// Outline of a query, B placed by a pose (the stages below, composed by `distance` and by
// `within`):
//   place    B's vertices and nodes as placed, computed where the later stages meet them;
//   nested   a vertex of one strictly inside the other solid: distance 0 at once;
//   Descent  the branch and bound over node pairs (bvh::nearest_pairs), leaving contenders and
//            the lowest meeting pair; `within` stops at the first meeting pair;
//   closest  the exact winner among the contenders (least_contender.h);
// then `distance` rounds it once and `within` compares it with d exactly.

namespace contain::distance {

namespace {

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

}  // namespace

struct MeshPairDistance::Volumes {
  std::vector<detail::OrientedBox> a, b;
  double extent_a = 0, extent_b = 0;
  std::vector<std::int32_t> min_a, min_b;  // the lowest triangle under each node
};

struct MeshPairDistance::Closest {
  predicates::FlatPair3 pair{};
  std::int32_t a = -1, b = -1;
  std::size_t contenders = 0;  // contenders left for the exact stage
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

const char* to_string(inside::PairWitness contact) {
  switch (contact) {
    case inside::PairWitness::triangles:
    case inside::PairWitness::edges:
      return "touching";
    case inside::PairWitness::vertex_of_a_in_b:
      return "vertex_of_a_in_b";
    case inside::PairWitness::vertex_of_b_in_a:
      return "vertex_of_b_in_a";
    case inside::PairWitness::none:
      break;
  }
  return "separate";
}

MeshPairDistance::MeshPairDistance(const Mesh& a, const Mesh& b,
                                   const MeshPairDistanceOptions& options)
    : pair_(a, b, options) {
  auto volumes = std::make_shared<Volumes>();
  volumes->a = detail::oriented_boxes(pair_.a.bvh, pair_.a.mesh);
  volumes->b = detail::oriented_boxes(pair_.b.bvh, pair_.b.mesh);
  volumes->extent_a = detail::oriented_extent(volumes->a);
  volumes->extent_b = detail::oriented_extent(volumes->b);
  volumes->min_a = least_items(pair_.a.bvh);
  volumes->min_b = least_items(pair_.b.bvh);
  volumes_ = std::move(volumes);
}

// B as placed by one pose, each piece computed on first use (a stamp per vertex and per node):
// the descent meets a few thousand of B's vertices and nodes, and placing all of them cost
// 0.2 ms per pose on the 100k-triangle bench, a fifth of FCL's whole query. Thread-local, reset
// by every query.
struct MeshPairDistance::Placed {
  Transform tb;
  PlacedVertices vertices;
  double slack = 0;  // triangle_pair_bounds' slack for A's and B's placed coordinates
  // Per node of B: the centre of its oriented box as placed (the bound's direction), and for
  // leaves the exact box of the placed triangles.
  std::vector<Vec3> centre;
  std::vector<Box3> leaf_box;
  std::vector<std::uint32_t> centre_stamp, box_stamp;
  std::uint32_t stamp = 0;
  std::vector<detail::PairContender> contenders;

  void reset(const MeshPairDistance& pair, const Transform& pose) {
    tb = pose;
    vertices.reset(pair.pair_.b.mesh.vertices, pose);
    slack = detail::triangle_slack(
        std::max(pair.pair_.a.max_abs, bvh::placed_max_abs(pose, pair.pair_.b.max_abs)));
    const std::size_t nodes = pair.pair_.b.bvh.nodes().size();
    if (box_stamp.size() < nodes || ++stamp == 0) {
      box_stamp.assign(std::max(box_stamp.size(), nodes), 0);
      centre_stamp.assign(box_stamp.size(), 0);
      leaf_box.resize(box_stamp.size());
      centre.resize(box_stamp.size());
      stamp = 1;
    }
    contenders.clear();
  }
  Vec3 centre_of(const detail::OrientedBox& box, std::int32_t k) {
    const auto u = static_cast<std::size_t>(k);
    if (centre_stamp[u] != stamp) {
      centre_stamp[u] = stamp;
      centre[u] = tb.apply(box.c);
    }
    return centre[u];
  }
  const Box3& leaf_box_of(const Mesh& b, const bvh::Bvh& tree, std::int32_t k) {
    const auto u = static_cast<std::size_t>(k);
    if (box_stamp[u] != stamp) {
      const bvh::Node& node = tree.nodes()[u];
      Box3 box;
      for (std::int32_t i = node.first; i < node.first + node.count; ++i)
        for (const std::int32_t v :
             b.triangles[static_cast<std::size_t>(tree.items()[static_cast<std::size_t>(i)])])
          box.expand(vertices[v]);
      box_stamp[u] = stamp;
      leaf_box[u] = box;
    }
    return leaf_box[u];
  }
};

// The descent (a bvh::nearest_pairs visitor): pairs of nodes, nearer first, pruned against the
// best upper bound. Node pairs are bounded by their oriented boxes (oriented_box.h: a separating
// axis along the line between the centres, with a proven rounding margin); leaf pairs then by
// the exact boxes of B's placed leaf triangles and the triangles' own bounds.
//
// Depth first, the nearer child pair first, so that the first leaf pairs reached are near the
// closest ones and the upper bound falls fast. A best-first heap visits fewer pairs (22k
// against 35k per pose on the armadillo bench, with axis-aligned boxes) but its upkeep costs
// more than they save (4.6 against 3.4 ms per pose).
//
// Touching: once a triangle pair is found to meet (exactly), the distance is 0 and the answer
// is the lowest meeting pair (distance-tie rule: lowest triangle of A, then of B). From then on
// best = 0 prunes every pair that surely does not meet, and a pair of nodes whose lowest
// triangles come at or after the pair found holds no lower pair. A `within` query stops at the
// first meeting pair instead: distance 0 is within any d >= 0.
struct MeshPairDistance::Descent {
  const MeshPairDistance& pair;
  Placed& placed;
  bool stop_at_meeting = false;
  std::span<const bvh::Node> na, nb;
  std::span<const std::int32_t> ia, ib, mins_a, mins_b;
  std::span<const detail::OrientedBox> oa, ob;
  detail::OrientedPose pose;
  double best = kInf;
  bool meet = false;  // a meeting pair was found: (meet_a, meet_b), the lowest so far
  std::int32_t meet_a = 0, meet_b = 0;

  Descent(const MeshPairDistance& p, Placed& w, bool stop)
      : pair(p),
        placed(w),
        stop_at_meeting(stop),
        na(p.pair_.a.bvh.nodes()),
        nb(p.pair_.b.bvh.nodes()),
        ia(p.pair_.a.bvh.items()),
        ib(p.pair_.b.bvh.items()),
        mins_a(p.volumes_->min_a),
        mins_b(p.volumes_->min_b),
        oa(p.volumes_->a),
        ob(p.volumes_->b),
        pose(detail::oriented_pose(w.tb, p.volumes_->extent_a, p.volumes_->extent_b)) {}

  // The size that decides which node to split: the oriented box's surface area (over 8).
  static double size(const detail::OrientedBox& o) {
    return o.h[0] * o.h[1] + o.h[1] * o.h[2] + o.h[2] * o.h[0];
  }
  bool at_or_after_meeting(std::int32_t ta, std::int32_t tb) const {
    return meet && (ta > meet_a || (ta == meet_a && tb >= meet_b));
  }

  double lower(std::int32_t a, std::int32_t b) {
    const detail::OrientedBox& box_b = ob[static_cast<std::size_t>(b)];
    return detail::oriented_box_lower(oa[static_cast<std::size_t>(a)], box_b,
                                      placed.centre_of(box_b, b), pose);
  }
  bool worth(const bvh::NodePair& e) const {
    return !(e.lower > best) && !at_or_after_meeting(mins_a[static_cast<std::size_t>(e.a)],
                                                     mins_b[static_cast<std::size_t>(e.b)]);
  }
  bool split_a(std::int32_t a, std::int32_t b) const {
    return size(oa[static_cast<std::size_t>(a)]) >= size(ob[static_cast<std::size_t>(b)]);
  }
  // Of two pairs at the same bound (two pairs that may touch), the one with the lower
  // triangles first: it finds the lowest meeting pair sooner.
  bool before(const bvh::NodePair& x, const bvh::NodePair& y) const {
    const auto ax = mins_a[static_cast<std::size_t>(x.a)],
               ay = mins_a[static_cast<std::size_t>(y.a)];
    return ax != ay ? ax < ay
                    : mins_b[static_cast<std::size_t>(x.b)] < mins_b[static_cast<std::size_t>(y.b)];
  }
  bvh::Visit leaves(std::int32_t a, std::int32_t b);
  bvh::Visit triangle_pair(std::int32_t ta, const Triangle3& tri_a, std::int32_t tb,
                           const Triangle3& tri_b);
};

// A pair of leaves: B's placed triangles and their boxes gathered once, a quick bound on the two
// sets first (boxes near each other often hold patches that face apart: most leaf pairs end
// there), then each triangle pair behind a box-gap check.
bvh::Visit MeshPairDistance::Descent::leaves(std::int32_t a, std::int32_t b) {
  const bvh::Node& p = na[static_cast<std::size_t>(a)];
  const bvh::Node& q = nb[static_cast<std::size_t>(b)];
  const Mesh& mesh_a = pair.pair_.a.mesh;
  const Mesh& mesh_b = pair.pair_.b.mesh;
  Triangle3 tris_b[kMaxLeaf];
  Box3 boxes_b[kMaxLeaf];
  const std::int32_t count_b = std::min<std::int32_t>(q.count, kMaxLeaf);
  const Box3& leaf_box_b = placed.leaf_box_of(mesh_b, pair.pair_.b.bvh, b);
  for (std::int32_t t = 0; t < count_b; ++t) {
    const std::int32_t tbi = ib[static_cast<std::size_t>(q.first + t)];
    tris_b[t] = placed.vertices.triangle(mesh_b.triangles[static_cast<std::size_t>(tbi)]);
    boxes_b[t] = bounding_box(tris_b[t]);
  }
  Triangle3 tris_a[kMaxLeaf];
  const std::int32_t count_a = std::min<std::int32_t>(p.count, kMaxLeaf);
  for (std::int32_t s = 0; s < count_a; ++s)
    tris_a[s] =
        mesh_a.triangle(static_cast<std::size_t>(ia[static_cast<std::size_t>(p.first + s)]));
  if (count_a == p.count && count_b == q.count) {
    const Vec3 w = (p.box.min + p.box.max) - (leaf_box_b.min + leaf_box_b.max);
    if (detail::triangle_sets_quick_lower(std::span<const Triangle3>(tris_a, count_a),
                                          std::span<const Triangle3>(tris_b, count_b), w) > best)
      return bvh::Visit::proceed;
  }
  for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
    const std::int32_t ta = ia[static_cast<std::size_t>(s)];
    const Triangle3 tri_a =
        s - p.first < count_a ? tris_a[s - p.first] : mesh_a.triangle(static_cast<std::size_t>(ta));
    const Box3 box_a = bounding_box(tri_a);
    if (box_box_lower_bound(box_a, leaf_box_b) > best) continue;
    for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
      const std::int32_t tbi = ib[static_cast<std::size_t>(t)];
      const std::int32_t k = t - q.first;
      if (at_or_after_meeting(ta, tbi)) continue;
      Triangle3 tri_b;
      if (k < count_b) {
        if (box_box_lower_bound(box_a, boxes_b[k]) > best) continue;
        tri_b = tris_b[k];
      } else {
        tri_b = placed.vertices.triangle(mesh_b.triangles[static_cast<std::size_t>(tbi)]);
      }
      if (triangle_pair(ta, tri_a, tbi, tri_b) == bvh::Visit::stop) return bvh::Visit::stop;
    }
  }
  return bvh::Visit::proceed;
}

// One triangle pair: bounded in floating point; a pair whose lower bound is 0 is tested
// exactly for meeting; otherwise it is a contender of the exact stage and lowers the best.
bvh::Visit MeshPairDistance::Descent::triangle_pair(std::int32_t ta, const Triangle3& tri_a,
                                                    std::int32_t tb, const Triangle3& tri_b) {
  if (detail::triangle_pair_quick_lower(tri_a, tri_b) > best) return bvh::Visit::proceed;
  double lo = 0, hi = 0;
  detail::triangle_pair_bounds(tri_a, tri_b, placed.slack, lo, hi);
  if (lo > best) return bvh::Visit::proceed;
  if (lo == 0 && predicates::flats_meet(predicates::closest_flats(tri_a, tri_b))) {
    if (stop_at_meeting) return bvh::Visit::stop;
    meet = true;
    meet_a = ta;
    meet_b = tb;
    best = 0;
    return bvh::Visit::proceed;
  }
  if (meet) return bvh::Visit::proceed;  // not meeting: not an answer any more
  placed.contenders.push_back({ta, tb, lo, hi});
  best = std::min(best, hi);
  return bvh::Visit::proceed;
}

MeshPairDistance::Placed& MeshPairDistance::place(const Transform& tb) const {
  thread_local Placed placed;
  placed.reset(*this, tb);
  return placed;
}

// Stage 1, overlap first: a vertex of one strictly inside the other solid makes the distance 0
// whatever the surfaces do (and settles nested solids, whose surfaces may be far apart, at
// once). A vertex on the other's surface is a touching pair, which the descent finds. Both
// solids are inside::MeshIndex's (the winding number positive, or ray parity for inconsistent
// orientation: solid_rule.h), A's by PlacedMeshPair::a_holds (its ray, or its index once built),
// B's by the signed ray as placed.
MeshPairDistance::Nested MeshPairDistance::nested(Placed& placed) const {
  if (pair_.a.solid()) {
    for (const std::int32_t v : pair_.b.components) {
      if (pair_.a_holds(placed.vertices[v]))
        return {inside::PairWitness::vertex_of_b_in_a, v, placed.vertices[v]};
    }
  }
  if (pair_.b.solid()) {
    const Mesh& b = pair_.b.mesh;
    const Sign orientation = inside::transform_orientation(placed.tb);
    for (const std::int32_t v : pair_.a.components) {
      const Vec3 q = pair_.a.mesh.vertex(v);
      const Location location = inside::locate_by_ray(
          pair_.b.bvh, q, pair_.b.rule, orientation,
          [&](const Box3& local) { return bvh::placed_box(local, placed.tb); },
          [&](std::int32_t t) {
            return placed.vertices.triangle(b.triangles[static_cast<std::size_t>(t)]);
          });
      if (location == Location::inside) return {inside::PairWitness::vertex_of_a_in_b, v, q};
    }
  }
  return {};
}

// Stage 3, exact: the least exact distance among the contenders the descent left (ties to the
// lowest triangle of A, then of B); the lowest meeting pair when one met.
MeshPairDistance::Closest MeshPairDistance::closest(Descent& descent) const {
  std::vector<detail::PairContender>& contenders = descent.placed.contenders;
  if (descent.meet) {  // the lowest meeting pair is the answer; the other contenders are farther
    contenders.clear();
    contenders.push_back({descent.meet_a, descent.meet_b, 0, 0});
  }
  const detail::LeastContender<predicates::FlatPair3> winner =
      detail::least_contender(contenders, descent.best, [&](std::int32_t a, std::int32_t b) {
        return predicates::closest_flats(
            pair_.a.mesh.triangle(static_cast<std::size_t>(a)),
            descent.placed.vertices.triangle(pair_.b.mesh.triangles[static_cast<std::size_t>(b)]));
      });
  return {winner.pair, winner.a, winner.b, contenders.size()};
}

PairDistance3 MeshPairDistance::distance(const Transform& transform_b) const {
  PairDistance3 out;
  if (pair_.a.bvh.empty() || pair_.b.bvh.empty()) {
    out.distance = kInf;
    return out;
  }
  Placed& placed = place(transform_b);
  if (const Nested n = nested(placed); n.vertex >= 0) {
    out.contact = n.contact;
    out.vertex = n.vertex;
    out.point_a = out.point_b = n.point;
    out.distance = 0.0;
    return out;
  }
  Descent descent(*this, placed, false);
  out.node_pairs = bvh::nearest_pairs(pair_.a.bvh, pair_.b.bvh, descent).nodes;
  const Closest c = closest(descent);
  out.contenders = c.contenders;
  out.triangle_a = c.a;
  out.triangle_b = c.b;
  out.contact =
      predicates::flats_meet(c.pair) ? inside::PairWitness::triangles : inside::PairWitness::none;
  out.distance = predicates::rounded_distance(c.pair);
  const predicates::ClosestPoints3 points = predicates::rounded_closest_points(c.pair);
  out.point_a = points.a;
  out.point_b = points.b;
  return out;
}

bool MeshPairDistance::within(const Transform& transform_b, double d) const {
  if (!(d >= 0) || pair_.a.bvh.empty() || pair_.b.bvh.empty()) return false;
  Placed& placed = place(transform_b);
  if (nested(placed).vertex >= 0) return true;
  Descent descent(*this, placed, true);
  if (bvh::nearest_pairs(pair_.a.bvh, pair_.b.bvh, descent).stopped) return true;  // they meet
  const Closest c = closest(descent);
  return predicates::flats_meet(c.pair) ||
         predicates::compare_squared_distance(c.pair, d) != Sign::positive;
}
void MeshPairDistance::distance(std::span<const Transform> poses, std::span<PairDistance3> out,
                                const BatchOptions& options) const {
  // Poses are heavy items: one is enough for a thread.
  batch_map(poses, out, options, 1, [&](const Transform& pose) { return distance(pose); });
}

void MeshPairDistance::within(std::span<const Transform> poses, double d,
                              std::span<std::uint8_t> out, const BatchOptions& options) const {
  batch_map(poses, out, options, 1,
            [&](const Transform& pose) -> std::uint8_t { return within(pose, d) ? 1 : 0; });
}

PairDistance3 mesh_mesh(const Mesh& a, const Mesh& b, const Transform& transform_a,
                        const Transform& transform_b) {
  return MeshPairDistance(a, b, {.transform_a = transform_a}).distance(transform_b);
}

}  // namespace contain::distance
