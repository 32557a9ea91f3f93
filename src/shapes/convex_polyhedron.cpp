#include "contain/shapes/convex_polyhedron.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"

namespace contain::shapes {
namespace {

bool finite(const Plane& p) {
  return std::isfinite(p.a) && std::isfinite(p.b) && std::isfinite(p.c) && std::isfinite(p.d);
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return predicates::orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero &&
         predicates::orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero &&
         predicates::orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero;
}

bool lexicographic_less(Vec3 p, Vec3 q) {
  return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
}

// Positive inside face t (outward counter-clockwise), zero on its plane.
Sign inner_side(const Triangle3& t, Vec3 p) {
  return -predicates::orient3d(t.a, t.b, t.c, p);
}

// Closed and consistently oriented: every directed edge used once and its twin once, indices in
// range. The first failure, or nothing.
std::optional<Error> closed_and_oriented(const Mesh& mesh) {
  if (mesh.triangles.size() < 4) {
    return Error{ErrorKind::degenerate, "a closed convex mesh needs at least 4 triangles, got " +
                                            std::to_string(mesh.triangles.size())};
  }
  const auto count = static_cast<std::int64_t>(mesh.vertices.size());
  std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t i = tri[static_cast<std::size_t>(k)];
      if (i < 0 || i >= count) {
        return Error{ErrorKind::invalid_value,
                     "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(i)};
      }
      ++directed[{i, tri[static_cast<std::size_t>((k + 1) % 3)]}];
    }
  }
  for (const auto& [edge, uses] : directed) {
    const auto twin = directed.find({edge.second, edge.first});
    if (uses != 1 || twin == directed.end() || twin->second != 1) {
      return Error{ErrorKind::invalid_value,
                   "the mesh is not closed and consistently oriented at edge " +
                       std::to_string(edge.first) + "-" + std::to_string(edge.second)};
    }
  }
  return std::nullopt;
}

// Convexity: every vertex on the inner side of (or on) every face plane. A consistently
// oriented closed convex mesh has all vertices on one side of every face: the inner side if
// it is oriented outward, the outer side if inward. Mixed sides mean "not convex". Flips
// inward faces outward.
std::optional<Error> orient_convex(std::vector<Triangle3>& faces, const Mesh& mesh,
                                   const std::vector<bool>& used) {
  bool any_inner = false, any_outer = false;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    bool face_inner = false, face_outer = false;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (!used[v]) continue;
      const Sign s = inner_side(faces[f], mesh.vertices[v]);
      face_inner = face_inner || s == Sign::positive;
      face_outer = face_outer || s == Sign::negative;
    }
    if (face_inner && face_outer) {
      return Error{ErrorKind::invalid_value,
                   "the mesh is not convex: vertices lie on both sides "
                   "of the plane of triangle " +
                       std::to_string(f)};
    }
    any_inner = any_inner || face_inner;
    any_outer = any_outer || face_outer;
  }
  if (any_inner && any_outer) {
    return Error{ErrorKind::invalid_value,
                 "the mesh is not convex: its faces do not all bound the same side"};
  }
  if (!any_inner && !any_outer) {
    return Error{ErrorKind::degenerate, "the mesh is flat: all its vertices are coplanar"};
  }
  if (any_outer) {
    for (Triangle3& f : faces)
      std::swap(f.b, f.c);  // oriented inward: flip
  }
  return std::nullopt;
}

// The corners once, sorted and distinct, so that a coordinate repeated under two indices of the
// mesh is one vertex of the solid (GJK's simplices name points, not indices).
void index_corners(const std::vector<Triangle3>& faces, std::vector<Vec3>& v,
                   std::vector<TriangleIndices>& face_indices) {
  for (const Triangle3& f : faces) {
    v.push_back(f.a);
    v.push_back(f.b);
    v.push_back(f.c);
  }
  std::sort(v.begin(), v.end(), lexicographic_less);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  const auto index_of = [&](Vec3 p) {
    return static_cast<std::int32_t>(std::lower_bound(v.begin(), v.end(), p, lexicographic_less) -
                                     v.begin());
  };
  face_indices.reserve(faces.size());
  for (const Triangle3& f : faces)
    face_indices.push_back({index_of(f.a), index_of(f.b), index_of(f.c)});
}

}  // namespace

Result<ConvexPolyhedron> ConvexPolyhedron::from_planes(std::vector<Plane> planes) {
  for (std::size_t i = 0; i < planes.size(); ++i) {
    if (!finite(planes[i])) {
      return Error{ErrorKind::invalid_value,
                   "plane " + std::to_string(i) + " has a NaN or infinite coefficient"};
    }
    if (planes[i].a == 0 && planes[i].b == 0 && planes[i].c == 0) {
      return Error{ErrorKind::degenerate, "plane " + std::to_string(i) + " has a zero normal"};
    }
  }
  ConvexPolyhedron result;
  result.planes_ = std::move(planes);
  return result;
}

Result<ConvexPolyhedron> ConvexPolyhedron::from_mesh(const Mesh& mesh) {
  if (auto error = closed_and_oriented(mesh)) return std::move(*error);
  std::vector<Triangle3> faces;
  faces.reserve(mesh.triangles.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 face = mesh.triangle(t);
    if (collinear(face.a, face.b, face.c)) {
      return Error{ErrorKind::degenerate, "triangle " + std::to_string(t) + " is degenerate"};
    }
    faces.push_back(face);
    for (std::int32_t i : mesh.triangles[t])
      used[static_cast<std::size_t>(i)] = true;
  }
  if (auto error = orient_convex(faces, mesh, used)) return std::move(*error);
  ConvexPolyhedron result;
  result.faces_ = std::move(faces);
  index_corners(result.faces_, result.vertices_, result.face_indices_);
  result.index_faces_around();
  return result;
}

ConvexPolyhedron ConvexPolyhedron::from_box(const Box3& box) {
  ConvexPolyhedron result;
  // Inward half-spaces x - min.x >= 0, max.x - x >= 0, ...: exact coefficients.
  result.planes_ = {Plane{1, 0, 0, -box.min.x}, Plane{-1, 0, 0, box.max.x},
                    Plane{0, 1, 0, -box.min.y}, Plane{0, -1, 0, box.max.y},
                    Plane{0, 0, 1, -box.min.z}, Plane{0, 0, -1, box.max.z}};
  for (int i = 0; i < 8; ++i) {
    result.vertices_.push_back({(i & 1) != 0 ? box.max.x : box.min.x,
                                (i & 2) != 0 ? box.max.y : box.min.y,
                                (i & 4) != 0 ? box.max.z : box.min.z});
  }
  // Two triangles per side (corner indices by bits x = 1, y = 2, z = 4), outward.
  static constexpr std::int32_t kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads) {
    result.face_indices_.push_back({q[0], q[1], q[2]});
    result.face_indices_.push_back({q[0], q[2], q[3]});
  }
  result.index_faces_around();
  return result;
}

// Compressed rows: count each vertex's faces, prefix-sum the counts into row starts, then fill
// the rows in face order (so each row is ascending).
void ConvexPolyhedron::index_faces_around() {
  around_start_.assign(vertices_.size() + 1, 0);
  for (const TriangleIndices& t : face_indices_)
    for (const std::int32_t k : t)
      ++around_start_[static_cast<std::size_t>(k) + 1];
  for (std::size_t k = 0; k < vertices_.size(); ++k)
    around_start_[k + 1] += around_start_[k];
  around_list_.resize(static_cast<std::size_t>(around_start_.back()));
  std::vector<std::int32_t> fill(around_start_.begin(), around_start_.end() - 1);
  for (std::size_t f = 0; f < face_indices_.size(); ++f)
    for (const std::int32_t k : face_indices_[f])
      around_list_[static_cast<std::size_t>(fill[static_cast<std::size_t>(k)]++)] =
          static_cast<std::int32_t>(f);
}

Triangle3 ConvexPolyhedron::face(std::int32_t k) const {
  const TriangleIndices& t = face_indices_[static_cast<std::size_t>(k)];
  return {vertices_[static_cast<std::size_t>(t[0])], vertices_[static_cast<std::size_t>(t[1])],
          vertices_[static_cast<std::size_t>(t[2])]};
}

std::span<const std::int32_t> ConvexPolyhedron::faces_around(std::int32_t v) const {
  const auto begin = static_cast<std::size_t>(around_start_[static_cast<std::size_t>(v)]);
  const auto end = static_cast<std::size_t>(around_start_[static_cast<std::size_t>(v) + 1]);
  return std::span<const std::int32_t>(around_list_).subspan(begin, end - begin);
}

std::int32_t ConvexPolyhedron::support_index(Vec3 direction) const {
  return shapes::support_index(vertices_, direction);
}

std::int32_t support_index(std::span<const Vec3> points, Vec3 direction) {
  if (points.empty()) return -1;
  std::size_t best = 0;
  double best_dot = dot(direction, points[0]);
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double d = dot(direction, points[k]);
    if (d > best_dot) {
      best_dot = d;
      best = k;
    }
  }
  return static_cast<std::int32_t>(best);
}

Vec3 ConvexPolyhedron::support(Vec3 direction) const {
  const std::int32_t k = support_index(direction);
  if (k < 0) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  return vertices_[static_cast<std::size_t>(k)];
}

}  // namespace contain::shapes
