#include "contain/shapes/convex_polyhedron.h"

#include <cmath>
#include <cstdint>
#include <map>
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

// Positive inside face t (outward counter-clockwise), zero on its plane.
Sign inner_side(const Triangle3& t, Vec3 p) {
  return -predicates::orient3d(t.a, t.b, t.c, p);
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
  std::vector<Triangle3> faces;
  faces.reserve(mesh.triangles.size());
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    const Triangle3 face{mesh.vertices[static_cast<std::size_t>(tri[0])],
                         mesh.vertices[static_cast<std::size_t>(tri[1])],
                         mesh.vertices[static_cast<std::size_t>(tri[2])]};
    if (collinear(face.a, face.b, face.c)) {
      return Error{ErrorKind::degenerate, "triangle " + std::to_string(t) + " is degenerate"};
    }
    faces.push_back(face);
    for (std::int32_t i : tri)
      used[static_cast<std::size_t>(i)] = true;
  }
  // Convexity: every vertex on the inner side of (or on) every face plane. A consistently
  // oriented closed convex mesh has all vertices on one side of every face: the inner side if
  // it is oriented outward, the outer side if inward. Mixed sides mean "not convex".
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
  ConvexPolyhedron result;
  result.faces_ = std::move(faces);
  return result;
}

}  // namespace contain::shapes
