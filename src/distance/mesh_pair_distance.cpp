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
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"
#include "distance/flat_answer.h"
#include "distance/search_tree.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

constexpr double kEps = 0x1p-53;
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

double box_box_lower_bound(const Box3& a, const Box3& b) {
  const double dx = std::max({a.min.x - b.max.x, b.min.x - a.max.x, 0.0});
  const double dy = std::max({a.min.y - b.max.y, b.min.y - a.max.y, 0.0});
  const double dz = std::max({a.min.z - b.max.z, b.min.z - a.max.z, 0.0});
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

struct PairContender {
  std::int32_t a, b;
  double lo, hi;
};

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
  thread_local std::vector<Vec3> wb;
  wb.resize(b_.vertices.size());
  for (std::size_t i = 0; i < wb.size(); ++i)
    wb[i] = tb.apply(b_.vertices[i]);
  double placed_max = 0;
  for (const Vec3& v : wb)
    placed_max = std::max({placed_max, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  const double slack = detail::triangle_slack(std::max(a_max_abs_, placed_max));
  // 1. Overlap first: a vertex of one inside the other solid makes the distance 0 whatever the
  // surfaces do (and settles nested solids, whose surfaces may be far apart, at once).
  if (a_solid_) {
    for (const std::int32_t v : b_components_) {
      if (index_a_.locate(wb[static_cast<std::size_t>(v)]) == Location::inside) {
        out.contact = PairContact::vertex_of_b_in_a;
        out.vertex = v;
        out.point_a = out.point_b = wb[static_cast<std::size_t>(v)];
        out.distance = 0.0;
        if (within_out) *within_out = true;
        return out;
      }
    }
  }
  // B's hierarchy refitted to B as placed: the same tree, each box the exact box of its placed
  // triangles (children come after their parent, so one backward pass). O(n), and no box grows
  // with the rotation as a mapped local box would.
  const std::span<const bvh::Node> nb_local = bvh_b_.nodes();
  thread_local std::vector<Box3> refit;
  refit.assign(nb_local.size(), Box3{});
  for (std::size_t k = nb_local.size(); k-- > 0;) {
    const bvh::Node& node = nb_local[k];
    Box3 box;
    if (node.is_leaf()) {
      for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
        const TriangleIndices& t =
            b_.triangles[static_cast<std::size_t>(bvh_b_.items()[static_cast<std::size_t>(i)])];
        for (const std::int32_t v : t)
          box.expand(wb[static_cast<std::size_t>(v)]);
      }
    } else {
      box = refit[k + 1];
      box.expand(refit[static_cast<std::size_t>(node.first)]);
    }
    refit[k] = box;
  }

  if (b_solid_) {
    for (const std::int32_t v : a_components_) {
      const Vec3 q = a_world_.vertices[static_cast<std::size_t>(v)];
      bool odd = false;
      bool on_surface = false;
      // The perturbed ray along +x against B as placed, culled by B's placed boxes; a vertex on
      // B's surface is a touching pair, which the descent finds.
      (void)bvh_b_.traverse(
          [&](const bvh::Node&, std::int32_t index) {
            const Box3& w = refit[static_cast<std::size_t>(index)];
            return w.max.x >= q.x && w.min.y <= q.y && q.y <= w.max.y && w.min.z <= q.z &&
                   q.z <= w.max.z;
          },
          [&](std::int32_t t) {
            const Triangle3 tri = triangle_of(wb, b_.triangles[static_cast<std::size_t>(t)]);
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

  // 2. The descent: pairs of nodes, nearer first, pruned against the best upper bound.
  const std::span<const bvh::Node> na = bvh_a_.nodes(), nb = bvh_b_.nodes();
  const std::span<const std::int32_t> ia = bvh_a_.items(), ib = bvh_b_.items();
  struct Entry {
    std::int32_t a, b;
    double lb;
    Box3 box_b;  // node b placed
  };
  thread_local std::vector<Entry> stack;
  thread_local std::vector<PairContender> contenders;
  stack.clear();
  contenders.clear();
  double best = kInf;
  const Box3 root_b = refit[0];
  // Best first: the pair of nodes with the least lower bound is expanded next (a min-heap), so
  // that the first leaf pairs reached are near the closest ones and the upper bound falls fast.
  const auto farther = [](const Entry& x, const Entry& y) { return x.lb > y.lb; };
  auto push = [&](const Entry& e) {
    if (e.lb > best) return;
    stack.push_back(e);
    std::push_heap(stack.begin(), stack.end(), farther);
  };
  push({0, 0, box_box_lower_bound(na[0].box, root_b), root_b});
  while (!stack.empty()) {
    std::pop_heap(stack.begin(), stack.end(), farther);
    const Entry e = stack.back();
    stack.pop_back();
    if (e.lb > best) break;  // every other entry is farther still
    ++out.node_pairs;
    const bvh::Node& p = na[static_cast<std::size_t>(e.a)];
    const bvh::Node& q = nb[static_cast<std::size_t>(e.b)];
    if (p.is_leaf() && q.is_leaf()) {
      for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
        const std::int32_t ta = ia[static_cast<std::size_t>(s)];
        const Triangle3 tri_a =
            triangle_of(a_world_.vertices, a_world_.triangles[static_cast<std::size_t>(ta)]);
        for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
          const std::int32_t tbi = ib[static_cast<std::size_t>(t)];
          const Triangle3 tri_b = triangle_of(wb, b_.triangles[static_cast<std::size_t>(tbi)]);
          double lo = 0, hi = 0;
          detail::triangle_pair_bounds(tri_a, tri_b, slack, lo, hi);
          if (lo > best) continue;
          contenders.push_back({ta, tbi, lo, hi});
          best = std::min(best, hi);
        }
      }
      continue;
    }
    const bool split_a =
        q.is_leaf() || (!p.is_leaf() && bvh::surface_area(p.box) >= bvh::surface_area(e.box_b));
    Entry c1 = e, c2 = e;
    if (split_a) {
      c1.a = e.a + 1;
      c2.a = p.first;
      c1.lb = box_box_lower_bound(na[static_cast<std::size_t>(c1.a)].box, e.box_b);
      c2.lb = box_box_lower_bound(na[static_cast<std::size_t>(c2.a)].box, e.box_b);
    } else {
      c1.b = e.b + 1;
      c2.b = q.first;
      c1.box_b = refit[static_cast<std::size_t>(c1.b)];
      c2.box_b = refit[static_cast<std::size_t>(c2.b)];
      c1.lb = box_box_lower_bound(p.box, c1.box_b);
      c2.lb = box_box_lower_bound(p.box, c2.box_b);
    }
    push(c1);
    push(c2);
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
        triangle_of(wb, b_.triangles[static_cast<std::size_t>(c.b)]));
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
