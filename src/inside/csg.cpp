#include "contain/inside/csg.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <type_traits>

#include "contain/inside/implicit.h"
#include "contain/inside/point_in_convex.h"
#include "contain/inside/point_in_triangle.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/predicates/side_of_plane.h"
#include "inside/csg_local.h"
#include "inside/mesh_ray.h"

namespace contain::inside {
namespace {

using detail::LocalConstraint;
using predicates::BigFloat;
using predicates::BigVec3;
using predicates::to_big;

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

bool finite(double v) {
  return std::isfinite(v);
}

// Empty string when the leaf is valid, else the reason; `kind` is set to what
// the reason is.
std::string check_leaf(const CsgLeaf& leaf, ErrorKind& kind) {
  kind = ErrorKind::invalid_value;
  return std::visit(
      Overloaded{
          [](const Sphere& s) -> std::string {
            if (!is_finite(s.center) || !finite(s.radius)) {
              return "sphere has a NaN or infinite number";
            }
            return s.radius < 0 ? "sphere radius is negative" : "";
          },
          [](const Box3& b) -> std::string {
            if (!is_finite(b.min) || !is_finite(b.max)) return "box has a NaN or infinite number";
            return b.empty() ? "box min exceeds max" : "";
          },
          [](const Plane& p) -> std::string {
            if (!finite(p.a) || !finite(p.b) || !finite(p.c) || !finite(p.d)) {
              return "halfspace has a NaN or infinite coefficient";
            }
            return p.a == 0 && p.b == 0 && p.c == 0 ? "halfspace normal is zero" : "";
          },
          [](const ConvexPolyhedron&) -> std::string { return ""; },  // validated when built
          [](const ImplicitFunction& f) -> std::string {
            return f ? "" : "implicit leaf holds no function";
          },
          [](const CsgMesh& m) -> std::string {
            const Mesh& mesh = m.mesh();
            const auto n = static_cast<std::int64_t>(mesh.vertices.size());
            for (const TriangleIndices& t : mesh.triangles) {
              if (std::any_of(t.begin(), t.end(),
                              [&](std::int32_t i) { return i < 0 || i >= n; })) {
                return "mesh has a vertex index out of range";
              }
            }
            if (!std::all_of(mesh.vertices.begin(), mesh.vertices.end(),
                             [](Vec3 v) { return is_finite(v); })) {
              return "mesh has a NaN or infinite coordinate";
            }
            return "";  // closedness is checked on its index (prepare)
          },
      },
      leaf);
}

// `mesh_index`: the index of a mesh leaf (null for other leaves).
Location locate_leaf(const CsgLeaf& leaf, const MeshIndex* mesh_index, Vec3 p) {
  return std::visit(Overloaded{
                        [&](const Sphere& s) { return point_in_sphere(s, p); },
                        [&](const Box3& b) { return point_in_box(b, p); },
                        [&](const Plane& h) { return point_in_halfspace(h, p); },
                        [&](const ConvexPolyhedron& c) { return point_in_convex(c, p); },
                        [&](const ImplicitFunction& f) { return point_in_implicit(f, p); },
                        [&](const CsgMesh&) {
                          // No index: a mesh without triangles, the empty solid.
                          return mesh_index != nullptr ? mesh_index->locate(p) : Location::outside;
                        },
                    },
                    leaf);
}

// The planes of the non-degenerate triangles that contain p: near p they carry the whole
// surface, so every open cell of their arrangement is in or out.
void mesh_constraints(const Mesh& mesh, Vec3 p, std::vector<LocalConstraint>& out) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    detail::add_plane_through(tri.a, tri.b, tri.c, p, out);
  }
}

// The mesh's signed crossings from the samples near p (inside/mesh_ray.h).
detail::MeshRay mesh_ray(const Mesh& mesh, Vec3 p) {
  detail::MeshRay ray(p);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    ray.add(tri.a, tri.b, tri.c);
  }
  return ray;
}

BigVec3 axis(int k, double s) {
  return to_big(Vec3{k == 0 ? s : 0.0, k == 1 ? s : 0.0, k == 2 ? s : 0.0});
}

// Central-difference gradient estimate of an implicit function (documented as
// approximate).
LocalConstraint implicit_constraint(const ImplicitFunction& f, Vec3 p) {
  const double size = std::max({1.0, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  const double step = 1e-6 * size;
  Vec3 gradient;
  bool all_nonnegative = true;
  double* parts[3] = {&gradient.x, &gradient.y, &gradient.z};
  for (int k = 0; k < 3; ++k) {
    const Vec3 e{k == 0 ? step : 0.0, k == 1 ? step : 0.0, k == 2 ? step : 0.0};
    const double ahead = f(p + e), behind = f(p - e);
    all_nonnegative = all_nonnegative && ahead >= 0 && behind >= 0;
    *parts[k] = ahead - behind;
  }
  LocalConstraint c;
  if (is_finite(gradient)) c.normal = to_big(gradient);
  c.fixed_value = all_nonnegative;  // used when the normal is zero
  return c;
}

// The planes through p that bound the leaf near p (p on the leaf's boundary),
// inward normals. Every leaf but a mesh fills exactly the cells on the positive
// side of all its constraints; a mesh's planes have no particular orientation
// and it classifies samples itself (MeshRay).
void local_constraints(const CsgLeaf& leaf, Vec3 p, std::vector<LocalConstraint>& out) {
  std::visit(
      Overloaded{
          [&](const Sphere& s) {
            // Tangent plane with inward normal c − p; |c − p| = r
            // exactly since p is on it. A ball of radius 0 has no
            // interior: its zero normal with fixed_value false.
            out.push_back({to_big(s.center) - to_big(p), true, false});
          },
          [&](const Box3& b) {
            const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
            const double q[3] = {p.x, p.y, p.z};
            for (int k = 0; k < 3; ++k) {
              if (q[k] == lo[k]) out.push_back({axis(k, 1.0), false, false});
              if (q[k] == hi[k]) out.push_back({axis(k, -1.0), false, false});
            }
          },
          [&](const Plane& h) {
            out.push_back({to_big(h.normal()), false, false});
          },
          [&](const ConvexPolyhedron& c) {
            for (const Plane& h : c.planes()) {
              if (predicates::side_of_plane(h, p) == Sign::zero) {
                out.push_back({to_big(h.normal()), false, false});
              }
            }
            for (const Triangle3& t : c.faces()) {
              if (predicates::orient3d(t.a, t.b, t.c, p) == Sign::zero) {
                const BigVec3 a = to_big(t.a);
                // Faces are counter-clockwise from outside: (b − a) × (c
                // − a) points out.
                out.push_back({-cross(to_big(t.b) - a, to_big(t.c) - a), false, false});
              }
            }
          },
          [&](const ImplicitFunction& f) { out.push_back(implicit_constraint(f, p)); },
          [&](const CsgMesh& m) { mesh_constraints(m.mesh(), p, out); },
      },
      leaf);
}

}  // namespace

Result<CsgSolid> CsgSolid::prepare(const Csg& tree, const MeshIndexOptions& mesh_options) {
  CsgSolid solid;
  // Breadth-first, so that children of a node are contiguous in children_.
  struct Pending {
    const Csg* tree;
    std::string path;
  };
  std::vector<Pending> queue{{&tree, ""}};
  std::map<const Mesh*, std::shared_ptr<const MeshIndex>> indexes;  // one per mesh, however shared
  solid.nodes_.push_back({});
  for (std::size_t at = 0; at < queue.size(); ++at) {
    // Copies: queue and nodes_ grow below.
    const Csg& t = *queue[at].tree;
    const std::string path = queue[at].path;
    solid.nodes_[at].op = t.op();
    if (t.op() == CsgOp::leaf) {
      ErrorKind kind = ErrorKind::invalid_value;
      const std::string problem = check_leaf(t.solid(), kind);
      if (!problem.empty()) return Error{kind, (path.empty() ? "" : path + ": ") + problem};
      std::shared_ptr<const MeshIndex> index;
      const auto* m = std::get_if<CsgMesh>(&t.solid());
      if (m != nullptr && !m->mesh().triangles.empty()) {  // none: the empty solid, no index
        std::shared_ptr<const MeshIndex>& shared = indexes[&m->mesh()];
        if (!shared) shared = std::make_shared<const MeshIndex>(m->mesh(), mesh_options);
        if (shared->regime() != MeshRegime::closed_exact) {
          const MeshReport& r = shared->report();
          return Error{ErrorKind::degenerate,
                       (path.empty() ? "" : path + ": ") +
                           "mesh is not closed, a closed mesh is required (triangles: " +
                           std::to_string(r.triangles) +
                           ", border edges: " + std::to_string(r.border_edges) +
                           ", non-manifold edges: " + std::to_string(r.nonmanifold_edges) + ")"};
        }
        index = shared;
      }
      solid.nodes_[at].first = static_cast<std::int32_t>(solid.leaves_.size());
      solid.leaves_.push_back(t.solid());
      solid.mesh_indexes_.push_back(std::move(index));
      continue;
    }
    const std::size_t arity = t.operands().size();
    if ((t.op() == CsgOp::difference && arity != 2) ||
        (t.op() == CsgOp::complement && arity != 1)) {
      return Error{ErrorKind::invalid_value, (path.empty() ? "" : path + ": ") +
                                                 shapes::to_string(t.op()) + " has " +
                                                 std::to_string(arity) + " operands"};
    }
    solid.nodes_[at].first = static_cast<std::int32_t>(solid.children_.size());
    solid.nodes_[at].count = static_cast<std::int32_t>(arity);
    for (std::size_t k = 0; k < arity; ++k) {
      solid.children_.push_back(static_cast<std::int32_t>(queue.size()));
      queue.push_back({&t.operands()[k], path + (path.empty() ? "" : ".") +
                                             shapes::to_string(t.op()) + "[" + std::to_string(k) +
                                             "]"});
      solid.nodes_.push_back({});
    }
  }
  return solid;
}

// Kleene three-valued evaluation: 1 in, -1 out, 0 unknown. With definite leaf
// values it is the plain boolean evaluation of the tree.
template <class LeafValue>
int CsgSolid::evaluate(std::int32_t index, const LeafValue& leaf_value) const {
  const Node& node = nodes_[static_cast<std::size_t>(index)];
  const auto child = [&](std::int32_t k) {
    return evaluate(children_[static_cast<std::size_t>(node.first + k)], leaf_value);
  };
  switch (node.op) {
    case CsgOp::leaf:
      return leaf_value(node.first);
    case CsgOp::unite: {
      int result = -1;
      for (std::int32_t k = 0; k < node.count; ++k) {
        const int v = child(k);
        if (v == 1) return 1;
        result = std::max(result, v);
      }
      return result;
    }
    case CsgOp::intersection: {
      int result = 1;
      for (std::int32_t k = 0; k < node.count; ++k) {
        const int v = child(k);
        if (v == -1) return -1;
        result = std::min(result, v);
      }
      return result;
    }
    case CsgOp::difference: {
      const int a = child(0);
      if (a == -1) return -1;
      return std::min(a, -child(1));
    }
    case CsgOp::complement:
      return -child(0);
  }
  return -1;
}

Location CsgSolid::locate(Vec3 p) const {
  std::vector<Location> at(leaves_.size());
  bool any_boundary = false;
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    at[i] = locate_leaf(leaves_[i], mesh_indexes_[i].get(), p);
    any_boundary = any_boundary || at[i] == Location::boundary;
  }
  const int known = evaluate(0, [&](std::int32_t leaf) {
    return static_cast<int>(at[static_cast<std::size_t>(leaf)]);  // boundary is 0: unknown
  });
  if (known != 0 || !any_boundary) return known > 0 ? Location::inside : Location::outside;
  // One leaf on whose boundary p lies, and the tree depends on it: every leaf node appears once in
  // the tree, so the three-valued evaluation is exact and both of its values occur near p. For a
  // mesh of the solid's rule, `boundary` from its index already means cells of both kinds around
  // p (inside/surface_star.h), so p is on the boundary without sampling the planes through it.
  if (std::count(at.begin(), at.end(), Location::boundary) == 1) {
    const auto i =
        static_cast<std::size_t>(std::find(at.begin(), at.end(), Location::boundary) - at.begin());
    if (mesh_indexes_[i] && mesh_indexes_[i]->inside_by_count(2)) return Location::boundary;
  }

  // p is on the boundary of leaves that matter: analyse its neighbourhood.
  std::vector<LocalConstraint> constraints;
  std::vector<std::int32_t> first(leaves_.size() + 1, 0);
  std::vector<detail::MeshRay> rays;  // per leaf, for meshes on whose surface p lies
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    first[i] = static_cast<std::int32_t>(constraints.size());
    if (at[i] == Location::boundary) {
      local_constraints(leaves_[i], p, constraints);
      if (const auto* m = std::get_if<CsgMesh>(&leaves_[i])) {
        rays.resize(leaves_.size());
        rays[i] = mesh_ray(m->mesh(), p);
      }
    }
    first[i + 1] = static_cast<std::int32_t>(constraints.size());
  }
  const detail::SolidContains contains = [&](std::span<const char> positive,
                                             const detail::SymbolicOffset& sample) {
    return evaluate(0, [&](std::int32_t leaf) {
             const auto i = static_cast<std::size_t>(leaf);
             if (at[i] != Location::boundary) return static_cast<int>(at[i]);
             if (std::holds_alternative<CsgMesh>(leaves_[i])) {
               return mesh_indexes_[i]->inside_by_count(rays[i].winding(sample)) ? 1 : -1;
             }
             for (std::int32_t k = first[i]; k < first[i + 1]; ++k) {
               if (positive[static_cast<std::size_t>(k)] == 0) return -1;
             }
             return 1;
           }) > 0;
  };
  return detail::classify_neighbourhood(constraints, contains);
}

void CsgSolid::locate(std::span<const Vec3> points, std::span<Location> out,
                      const BatchOptions& options) const {
  batch_map(points, out, options, 4096, [&](Vec3 p) { return locate(p); });
}

Location point_in_csg(const CsgSolid& solid, Vec3 p) {
  return solid.locate(p);
}

}  // namespace contain::inside
