#include "contain/collide/moving_mesh_pair.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "collide/placed_boxes.h"
#include "contain/bvh/nearest_pairs.h"
#include "contain/collide/ccd.h"

namespace contain::collide {
namespace {

Box3 box_of(std::initializer_list<Vec3> points) {
  Box3 b;
  for (const Vec3& p : points)
    b.expand(p);
  return b;
}

Box3 united(Box3 a, const Box3& b) {
  a.expand(b);
  return a;
}

// An id per undirected edge of a mesh, and per triangle the ids of its edges k -> k + 1.
std::vector<std::array<std::int32_t, 3>> edge_ids(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, std::int32_t> ids;
  std::vector<std::array<std::int32_t, 3>> out(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(mesh.triangles[t][static_cast<std::size_t>(k)]);
      const auto b =
          static_cast<std::uint32_t>(mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)]);
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const auto [it, added] = ids.try_emplace(key, static_cast<std::int32_t>(ids.size()));
      out[t][static_cast<std::size_t>(k)] = it->second;
    }
  }
  return out;
}

// A lower bound of the first time in [0, 1] at which two moving boxes can overlap, or +inf when
// they cannot before `limit`. A box whose corners move from b0 to b1 holds, at time t, every
// point it held at 0 moved linearly to where it is at 1 inside (1 - t) b0 + t b1; so each of
// the six separations, g(t) = hi_b(t) - lo_a(t) >= 0 and the like, is linear in t. Each is
// widened by 2^-40 of its terms' magnitude (far above the roundings of computing it) and the
// crossing times moved outward by 2^-40, so the bound is never late.
double entry_time(const Box3& a0, const Box3& a1, const Box3& b0, const Box3& b1, double limit) {
  double t_in = 0.0, t_out = 1.0;
  const auto constrain = [&](double hi0, double lo0, double hi1, double lo1) {
    const double margin =
        0x1p-40 * (std::fabs(hi0) + std::fabs(lo0) + std::fabs(hi1) + std::fabs(lo1)) + DBL_MIN;
    const double g0 = (hi0 - lo0) + margin, g1 = (hi1 - lo1) + margin;
    if (g0 >= 0.0 && g1 >= 0.0) return;
    if (g0 < 0.0 && g1 < 0.0) {
      t_in = INFINITY;
      return;
    }
    const double crossing = g0 / (g0 - g1);
    if (g0 < 0.0) {
      t_in = std::max(t_in, crossing * (1.0 - 0x1p-40));
    } else {
      t_out = std::min(t_out, crossing * (1.0 + 0x1p-40));
    }
  };
  constrain(b0.max.x, a0.min.x, b1.max.x, a1.min.x);
  constrain(a0.max.x, b0.min.x, a1.max.x, b1.min.x);
  constrain(b0.max.y, a0.min.y, b1.max.y, a1.min.y);
  constrain(a0.max.y, b0.min.y, a1.max.y, b1.min.y);
  constrain(b0.max.z, a0.min.z, b1.max.z, a1.min.z);
  constrain(a0.max.z, b0.min.z, a1.max.z, b1.min.z);
  if (!(t_in <= t_out) || t_in > limit) return INFINITY;
  return t_in;
}

// The boxes of every node at t = 0 and t = 1, from the items' boxes: nodes are stored depth
// first (children after their parent), so one pass from the back fills them.
void node_boxes(const bvh::Bvh& bvh, std::span<const Box3> items0, std::span<const Box3> items1,
                std::vector<Box3>& box0, std::vector<Box3>& box1) {
  const std::span<const bvh::Node> nodes = bvh.nodes();
  box0.assign(nodes.size(), Box3{});
  box1.assign(nodes.size(), Box3{});
  for (std::size_t n = nodes.size(); n-- > 0;) {
    const bvh::Node& node = nodes[n];
    if (node.is_leaf()) {
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto item = static_cast<std::size_t>(bvh.items()[static_cast<std::size_t>(k)]);
        box0[n].expand(items0[item]);
        box1[n].expand(items1[item]);
      }
    } else {
      for (const std::size_t child : {n + 1, static_cast<std::size_t>(node.first)}) {
        box0[n].expand(box0[child]);
        box1[n].expand(box1[child]);
      }
    }
  }
}

// A swept hierarchy over world positions at t = 0 and t = 1.
struct WorldSweep {
  bvh::Bvh bvh;
  std::vector<Box3> box0, box1;
};

WorldSweep world_sweep(const Mesh& mesh, std::span<const Vec3> at0, std::span<const Vec3> at1,
                       const bvh::BuildOptions& options) {
  std::vector<Box3> b0(mesh.triangles.size()), b1(mesh.triangles.size()), both(b0.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    const auto v = [&](std::span<const Vec3> p, int k) {
      return p[static_cast<std::size_t>(tri[static_cast<std::size_t>(k)])];
    };
    b0[t] = box_of({v(at0, 0), v(at0, 1), v(at0, 2)});
    b1[t] = box_of({v(at1, 0), v(at1, 1), v(at1, 2)});
    both[t] = united(b0[t], b1[t]);
  }
  WorldSweep s;
  s.bvh = bvh::Bvh(both, options);
  node_boxes(s.bvh, b0, b1, s.box0, s.box1);
  return s;
}

// The order in which witnesses of equal times are preferred.
using WitnessKey = std::tuple<double, int, std::int32_t, std::int32_t, std::int32_t, std::int32_t>;

WitnessKey key_of(const MeshImpact& m) {
  switch (m.witness) {
    case MeshImpactWitness::vertex_a_face_b:
      return {m.time, 0, m.vertex, m.triangle, 0, 0};
    case MeshImpactWitness::vertex_b_face_a:
      return {m.time, 1, m.vertex, m.triangle, 0, 0};
    case MeshImpactWitness::edges:
      return {m.time, 2, m.edge_a[0], m.edge_a[1], m.edge_b[0], m.edge_b[1]};
    default:
      break;
  }
  return {m.time, 3, 0, 0, 0, 0};
}

}  // namespace

// The primitives a query has decided already: a vertex is in ~6 triangles and an edge in 2, so
// the triangle pairs repeat most primitives. Keys: kind in the top bits, then two 31-bit ids
// (vertex and triangle, or edge and edge).
struct MovingMeshPair::Tested {
  std::unordered_set<std::uint64_t> keys;
  bool first_time(std::uint64_t kind, std::int32_t a, std::int32_t b) {
    return keys
        .insert((kind << 62) | (static_cast<std::uint64_t>(a) << 31) |
                static_cast<std::uint64_t>(b))
        .second;
  }
};

// B's side of a query: positions and node boxes, either through two placements of its own frame
// or from world positions with their own hierarchy.
struct MovingMeshPair::Side {
  const Mesh* mesh = nullptr;
  std::span<const std::array<std::int32_t, 3>> edges;  // per triangle of B: its edges' ids
  // Rigid: B's local vertices placed by `motion`, its local hierarchy's boxes placed by both.
  const Motion* motion = nullptr;
  std::optional<detail::PlacedBoxes> place0, place1;
  const bvh::Bvh* bvh = nullptr;
  // Deforming: world positions and a hierarchy over them.
  std::span<const Vec3> at0, at1;
  const WorldSweep* sweep = nullptr;

  [[nodiscard]] Vec3 position(std::int32_t v, int time) const {
    const Vec3 local = mesh->vertex(v);
    if (motion != nullptr) return time == 0 ? motion->from.apply(local) : motion->to.apply(local);
    return (time == 0 ? at0 : at1)[static_cast<std::size_t>(v)];
  }
  void boxes(const bvh::Node& node, std::size_t index, Box3& b0, Box3& b1) const {
    if (motion != nullptr) {
      b0 = (*place0)(node.box);
      b1 = (*place1)(node.box);
    } else {
      b0 = sweep->box0[index];
      b1 = sweep->box1[index];
    }
  }
};

MovingMeshPair::MovingMeshPair(const Mesh& a, const Mesh& b, const MovingMeshPairOptions& options)
    : a_(a),
      discrete_a_(a, b,
                  {.transform_a = options.a_at1.empty() ? options.motion_a.from : Transform{},
                   .bvh = options.bvh}),
      bvh_options_(options.bvh) {
  a0_.resize(a.vertices.size());
  a1_.resize(a.vertices.size());
  const bool deforming = !options.a_at1.empty();
  assert(!deforming || options.a_at1.size() == a.vertices.size());
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    a0_[v] = deforming ? a.vertices[v] : options.motion_a.from.apply(a.vertices[v]);
    a1_[v] = deforming ? options.a_at1[v] : options.motion_a.to.apply(a.vertices[v]);
  }
  WorldSweep sweep = world_sweep(a_, a0_, a1_, options.bvh);
  bvh_a_ = std::move(sweep.bvh);
  a_box0_ = std::move(sweep.box0);
  a_box1_ = std::move(sweep.box1);
  a_edges_ = edge_ids(a_);
  b_edges_ = edge_ids(b);
}

// Triangle ta of A against triangle tb of B: their 6 vertex-face and 9 edge-edge primitives,
// when the triangles' moving boxes can meet before `limit`; the best contact so far (time, then
// the witness order of ccd-mesh-rule) and the limit next(best time) are updated.
void MovingMeshPair::leaf_pair(const Side& side, std::int32_t ta, std::int32_t tb, double& limit,
                               MeshImpact& best, Tested& tested) const {
  const TriangleIndices& x = a_.triangles[static_cast<std::size_t>(ta)];
  const TriangleIndices& y = side.mesh->triangles[static_cast<std::size_t>(tb)];
  Vec3 pa[2][3], pb[2][3];
  for (int k = 0; k < 3; ++k) {
    pa[0][k] = a0_[static_cast<std::size_t>(x[static_cast<std::size_t>(k)])];
    pa[1][k] = a1_[static_cast<std::size_t>(x[static_cast<std::size_t>(k)])];
    pb[0][k] = side.position(y[static_cast<std::size_t>(k)], 0);
    pb[1][k] = side.position(y[static_cast<std::size_t>(k)], 1);
  }
  const Box3 a_box0 = box_of({pa[0][0], pa[0][1], pa[0][2]});
  const Box3 a_box1 = box_of({pa[1][0], pa[1][1], pa[1][2]});
  const Box3 b_box0 = box_of({pb[0][0], pb[0][1], pb[0][2]});
  const Box3 b_box1 = box_of({pb[1][0], pb[1][1], pb[1][2]});
  if (entry_time(a_box0, a_box1, b_box0, b_box1, limit) > limit) return;
  const auto consider = [&](const MeshImpact& m) {
    if (!best.hit || key_of(m) < key_of(best)) {
      const std::size_t node_pairs = best.node_pairs, tests = best.primitive_tests;
      best = m;
      best.node_pairs = node_pairs;
      best.primitive_tests = tests;
      limit = std::min(1.0, std::nextafter(m.time, 2.0));
    }
  };
  // Vertex-face both ways, then the nine edge pairs.
  for (int side_a = 0; side_a < 2; ++side_a) {
    const auto& v = side_a == 0 ? pa : pb;
    const auto& f = side_a == 0 ? pb : pa;
    const TriangleIndices& vi = side_a == 0 ? x : y;
    const Box3& f0 = side_a == 0 ? b_box0 : a_box0;
    const Box3& f1 = side_a == 0 ? b_box1 : a_box1;
    for (int k = 0; k < 3; ++k) {
      if (entry_time(box_of({v[0][k]}), box_of({v[1][k]}), f0, f1, limit) > limit) continue;
      if (!tested.first_time(static_cast<std::uint64_t>(side_a), vi[static_cast<std::size_t>(k)],
                             side_a == 0 ? tb : ta)) {
        continue;
      }
      ++best.primitive_tests;
      const Impact i =
          vertex_face_ccd({v[0][k], f[0][0], f[0][1], f[0][2], v[1][k], f[1][0], f[1][1], f[1][2]});
      if (!i.hit || i.time > limit) continue;
      MeshImpact m;
      m.hit = true;
      m.time = i.time;
      m.witness =
          side_a == 0 ? MeshImpactWitness::vertex_a_face_b : MeshImpactWitness::vertex_b_face_a;
      m.vertex = vi[static_cast<std::size_t>(k)];
      m.triangle = side_a == 0 ? tb : ta;
      m.initial = best.initial;
      consider(m);
    }
  }
  for (int ea = 0; ea < 3; ++ea) {
    const int ea1 = (ea + 1) % 3;
    for (int eb = 0; eb < 3; ++eb) {
      const int eb1 = (eb + 1) % 3;
      if (entry_time(box_of({pa[0][ea], pa[0][ea1]}), box_of({pa[1][ea], pa[1][ea1]}),
                     box_of({pb[0][eb], pb[0][eb1]}), box_of({pb[1][eb], pb[1][eb1]}),
                     limit) > limit) {
        continue;
      }
      if (!tested.first_time(
              2, a_edges_[static_cast<std::size_t>(ta)][static_cast<std::size_t>(ea)],
              side.edges[static_cast<std::size_t>(tb)][static_cast<std::size_t>(eb)])) {
        continue;
      }
      ++best.primitive_tests;
      const Impact i = edge_edge_ccd({pa[0][ea], pa[0][ea1], pb[0][eb], pb[0][eb1], pa[1][ea],
                                      pa[1][ea1], pb[1][eb], pb[1][eb1]});
      if (!i.hit || i.time > limit) continue;
      MeshImpact m;
      m.hit = true;
      m.time = i.time;
      m.witness = MeshImpactWitness::edges;
      // Each edge named by its vertex indices, the smaller first.
      const std::int32_t a0 = x[static_cast<std::size_t>(ea)],
                         a1 = x[static_cast<std::size_t>(ea1)];
      const std::int32_t b0 = y[static_cast<std::size_t>(eb)],
                         b1 = y[static_cast<std::size_t>(eb1)];
      m.edge_a = {std::min(a0, a1), std::max(a0, a1)};
      m.edge_b = {std::min(b0, b1), std::max(b0, b1)};
      m.initial = best.initial;
      consider(m);
    }
  }
}

MeshImpact MovingMeshPair::surfaces(const Side& side, MeshImpact best) const {
  const bvh::Bvh& bvh_b = side.motion != nullptr ? *side.bvh : side.sweep->bvh;
  if (bvh_a_.empty() || bvh_b.empty()) return best;
  // Best first: node pairs in the order of the earliest time their moving boxes can overlap,
  // so that the first contacts are found early and every pair that can only meet later than
  // the best time so far is never opened. Contacts that round down to the best time or below
  // happen before next(best) = `limit`.
  struct Descent {
    const MovingMeshPair& pair;
    const Side& side;
    const bvh::Bvh& bvh_b;
    MeshImpact& best;
    double limit = 1.0;
    Tested tested;

    void boxes_b(std::int32_t n, Box3& b0, Box3& b1) const {
      side.boxes(bvh_b.nodes()[static_cast<std::size_t>(n)], static_cast<std::size_t>(n), b0, b1);
    }
    double lower(std::int32_t a, std::int32_t b) {
      ++best.node_pairs;
      Box3 b0, b1;
      boxes_b(b, b0, b1);
      return entry_time(pair.a_box0_[static_cast<std::size_t>(a)],
                        pair.a_box1_[static_cast<std::size_t>(a)], b0, b1, limit);
    }
    bool worth(const bvh::NodePair& e) const { return e.lower <= limit; }
    bool split_a(std::int32_t a, std::int32_t b) const {
      Box3 q0, q1;
      boxes_b(b, q0, q1);
      return bvh::surface_area(united(pair.a_box0_[static_cast<std::size_t>(a)],
                                      pair.a_box1_[static_cast<std::size_t>(a)])) >=
             bvh::surface_area(united(q0, q1));
    }
    bvh::Visit leaves(std::int32_t a, std::int32_t b) {
      const bvh::Node& p = pair.bvh_a_.nodes()[static_cast<std::size_t>(a)];
      const bvh::Node& q = bvh_b.nodes()[static_cast<std::size_t>(b)];
      for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
        for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
          pair.leaf_pair(side, pair.bvh_a_.items()[static_cast<std::size_t>(s)],
                         bvh_b.items()[static_cast<std::size_t>(t)], limit, best, tested);
        }
      }
      return bvh::Visit::proceed;
    }
  };
  Descent descent{*this, side, bvh_b, best};
  (void)bvh::nearest_pairs(bvh_a_, bvh_b, descent, bvh::PairOrder::best_first);
  return best;
}

MeshImpact MovingMeshPair::first_contact(const Motion& motion_b) const {
  MeshImpact result;
  result.initial = discrete_a_.collide(motion_b.from);
  result.node_pairs = result.initial.node_pairs;
  if (result.initial.intersect) {
    result.hit = true;
    result.time = 0.0;
    result.witness = MeshImpactWitness::initial;
    return result;
  }
  Side side;
  side.mesh = &b().mesh;
  side.edges = b_edges_;
  side.motion = &motion_b;
  side.place0.emplace(motion_b.from, b().max_abs);
  side.place1.emplace(motion_b.to, b().max_abs);
  side.bvh = &b().bvh;
  return surfaces(side, result);
}

MeshImpact MovingMeshPair::first_contact(std::span<const Vec3> b_at1) const {
  assert(b_at1.size() == b().mesh.vertices.size());
  MeshImpact result;
  result.initial = discrete_a_.collide(Transform{});
  result.node_pairs = result.initial.node_pairs;
  if (result.initial.intersect) {
    result.hit = true;
    result.time = 0.0;
    result.witness = MeshImpactWitness::initial;
    return result;
  }
  const WorldSweep sweep = world_sweep(b().mesh, b().mesh.vertices, b_at1, bvh_options_);
  Side side;
  side.mesh = &b().mesh;
  side.edges = b_edges_;
  side.at0 = b().mesh.vertices;
  side.at1 = b_at1;
  side.sweep = &sweep;
  return surfaces(side, result);
}

void MovingMeshPair::first_contact(std::span<const Motion> motions_b, std::span<MeshImpact> out,
                                   const BatchOptions& options) const {
  batch_map(motions_b, out, options, 4096,
            [&](const Motion& motion) { return first_contact(motion); });
}

MeshImpact mesh_mesh_ccd(const Mesh& a, const Mesh& b, const Motion& motion_a,
                         const Motion& motion_b) {
  return MovingMeshPair(a, b, {.motion_a = motion_a}).first_contact(motion_b);
}

MeshImpact mesh_mesh_ccd(const Mesh& a, std::span<const Vec3> a_at1, const Mesh& b,
                         std::span<const Vec3> b_at1) {
  MovingMeshPairOptions options;
  options.a_at1.assign(a_at1.begin(), a_at1.end());
  return MovingMeshPair(a, b, options).first_contact(b_at1);
}

}  // namespace contain::collide
