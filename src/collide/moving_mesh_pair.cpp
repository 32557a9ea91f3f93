#include "contain/collide/moving_mesh_pair.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <optional>
#include <tuple>

#include "collide/placed_boxes.h"
#include "contain/bvh/triangle_boxes.h"
#include "contain/collide/ccd.h"

namespace contain::collide {
namespace {

constexpr double kUnit = 0x1p-53;

double max_abs(std::span<const Vec3> points) {
  double m = 0.0;
  for (const Vec3& v : points)
    m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return m;
}

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

// Every position at a time in [0, T] of a point moving on a segment whose ends lie in b0 and
// b1: the box of b0 and the interpolated box (1 - T) b0 + T b1, each bound moved out by a
// margin covering its three roundings and underflow.
Box3 swept_until(const Box3& b0, const Box3& b1, double t) {
  if (t >= 1.0) return united(b0, b1);
  const auto lerp = [t](double x0, double x1, double direction) {
    const double v = x0 + t * (x1 - x0);
    return v + direction * (4.0 * kUnit * (std::fabs(x0) + std::fabs(x1)) + DBL_MIN);
  };
  Box3 r = b0;
  r.expand(Vec3{lerp(b0.min.x, b1.min.x, -1), lerp(b0.min.y, b1.min.y, -1),
                lerp(b0.min.z, b1.min.z, -1)});
  r.expand(
      Vec3{lerp(b0.max.x, b1.max.x, 1), lerp(b0.max.y, b1.max.y, 1), lerp(b0.max.z, b1.max.z, 1)});
  return r;
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

// B's side of a query: positions and node boxes, either through two placements of its own frame
// or from world positions with their own hierarchy.
struct MovingMeshPair::Side {
  const Mesh* mesh = nullptr;
  // Rigid: B's local vertices placed by `motion`, its local hierarchy's boxes placed by both.
  const Motion* motion = nullptr;
  std::optional<detail::PlacedBoxes> place0, place1;
  const bvh::Bvh* bvh = nullptr;
  // Deforming: world positions and a hierarchy over them.
  std::span<const Vec3> at0, at1;
  const WorldSweep* sweep = nullptr;

  [[nodiscard]] Vec3 position(std::int32_t v, int time) const {
    const Vec3 local = mesh->vertices[static_cast<std::size_t>(v)];
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
      b_(b),
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
  bvh_b_ = bvh::Bvh(bvh::triangle_boxes(b_), options.bvh);
  b_max_abs_ = max_abs(b_.vertices);
}

MeshImpact MovingMeshPair::surfaces(const Side& side, MeshImpact best) const {
  const bvh::Bvh& bvh_b = side.motion != nullptr ? *side.bvh : side.sweep->bvh;
  if (bvh_a_.empty() || bvh_b.empty()) return best;
  const bvh::Node* nodes_a = bvh_a_.nodes().data();
  const bvh::Node* nodes_b = bvh_b.nodes().data();
  // Contacts that round down to the best time or below happen before next(best).
  double limit = 1.0;
  const auto consider = [&](const MeshImpact& m) {
    if (!best.hit || key_of(m) < key_of(best)) {
      best = m;
      limit = std::min(1.0, std::nextafter(m.time, 2.0));
    }
  };
  const bvh::TraversalStats stats = bvh::traverse_pairs(
      bvh_a_, bvh_b,
      [&](const bvh::Node& na, const bvh::Node& nb) {
        const auto ia = static_cast<std::size_t>(&na - nodes_a);
        const auto ib = static_cast<std::size_t>(&nb - nodes_b);
        Box3 b0, b1;
        side.boxes(nb, ib, b0, b1);
        return swept_until(a_box0_[ia], a_box1_[ia], limit).overlaps(swept_until(b0, b1, limit));
      },
      [&](std::int32_t ta, std::int32_t tb) {
        const TriangleIndices& x = a_.triangles[static_cast<std::size_t>(ta)];
        const TriangleIndices& y = side.mesh->triangles[static_cast<std::size_t>(tb)];
        Vec3 pa[2][3], pb[2][3];
        for (int k = 0; k < 3; ++k) {
          pa[0][k] = a0_[static_cast<std::size_t>(x[static_cast<std::size_t>(k)])];
          pa[1][k] = a1_[static_cast<std::size_t>(x[static_cast<std::size_t>(k)])];
          pb[0][k] = side.position(y[static_cast<std::size_t>(k)], 0);
          pb[1][k] = side.position(y[static_cast<std::size_t>(k)], 1);
        }
        const Box3 ba = swept_until(box_of({pa[0][0], pa[0][1], pa[0][2]}),
                                    box_of({pa[1][0], pa[1][1], pa[1][2]}), limit);
        const Box3 bb = swept_until(box_of({pb[0][0], pb[0][1], pb[0][2]}),
                                    box_of({pb[1][0], pb[1][1], pb[1][2]}), limit);
        if (!ba.overlaps(bb)) return bvh::Visit::proceed;
        // Vertex-face both ways, then the nine edge pairs.
        for (int side_a = 0; side_a < 2; ++side_a) {
          const auto& v = side_a == 0 ? pa : pb;
          const auto& f = side_a == 0 ? pb : pa;
          const TriangleIndices& vi = side_a == 0 ? x : y;
          for (int k = 0; k < 3; ++k) {
            ++best.primitive_tests;
            const Impact i = vertex_face_ccd(
                {v[0][k], f[0][0], f[0][1], f[0][2], v[1][k], f[1][0], f[1][1], f[1][2]});
            if (!i.hit || i.time > limit) continue;
            MeshImpact m;
            m.hit = true;
            m.time = i.time;
            m.witness = side_a == 0 ? MeshImpactWitness::vertex_a_face_b
                                    : MeshImpactWitness::vertex_b_face_a;
            m.vertex = vi[static_cast<std::size_t>(k)];
            m.triangle = side_a == 0 ? tb : ta;
            consider(m);
          }
        }
        for (int ea = 0; ea < 3; ++ea) {
          const int ea1 = (ea + 1) % 3;
          for (int eb = 0; eb < 3; ++eb) {
            const int eb1 = (eb + 1) % 3;
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
            consider(m);
          }
        }
        return bvh::Visit::proceed;
      });
  best.node_pairs += stats.nodes;
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
  side.mesh = &b_;
  side.motion = &motion_b;
  side.place0.emplace(motion_b.from, b_max_abs_);
  side.place1.emplace(motion_b.to, b_max_abs_);
  side.bvh = &bvh_b_;
  return surfaces(side, result);
}

MeshImpact MovingMeshPair::first_contact(std::span<const Vec3> b_at1) const {
  assert(b_at1.size() == b_.vertices.size());
  MeshImpact result;
  result.initial = discrete_a_.collide(Transform{});
  result.node_pairs = result.initial.node_pairs;
  if (result.initial.intersect) {
    result.hit = true;
    result.time = 0.0;
    result.witness = MeshImpactWitness::initial;
    return result;
  }
  const WorldSweep sweep = world_sweep(b_, b_.vertices, b_at1, bvh_options_);
  Side side;
  side.mesh = &b_;
  side.at0 = b_.vertices;
  side.at1 = b_at1;
  side.sweep = &sweep;
  return surfaces(side, result);
}

void MovingMeshPair::first_contact(std::span<const Motion> motions_b, std::span<MeshImpact> out,
                                   const BatchOptions& options) const {
  const std::size_t n = std::min(motions_b.size(), out.size());
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = first_contact(motions_b[i]);
  });
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
