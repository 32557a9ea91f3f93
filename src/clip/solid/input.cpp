// Stage 1 of the mesh boolean: the inputs as one soup, vertices welded by exact position (a
// point is one point whichever input names it), each input checked closed by the solids' rule
// (`unmatched_edge`: every directed edge as often as its reverse, so that its winding number is
// defined off its surface).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>

#include "clip/solid/engine.h"
#include "contain/predicates/orient2d.h"
#include "contain/shapes/mesh_closure.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;

std::string coordinates(Vec3 v) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << v.x << ", " << v.y << ", " << v.z << ')';
  return out.str();
}

// The error naming input `which`'s first unbalanced directed edge, if any: triangles [first,
// end) of the soup, whose vertices are already welded by exact position (-0 = +0), the welding
// of `unmatched_edge`, so the answer is its answer on the input without welding it again.
Status check_closed(const Soup& soup, std::size_t first, std::size_t which) {
  const std::optional<UnmatchedEdge> edge = unmatched_edge(
      soup.vertices, std::span<const TriangleIndices>(soup.triangles).subspan(first));
  if (!edge) return Ok{};
  return Error{.kind = ErrorKind::invalid_value,
               .message = "input " + std::to_string(which) + " is not closed: the directed edge " +
                          coordinates(edge->from) + " -> " + coordinates(edge->to) + " (triangle " +
                          std::to_string(edge->triangle) + ") occurs " +
                          std::to_string(edge->count) + " time(s), its reverse " +
                          std::to_string(edge->reverse)};
}

}  // namespace

int dropped_axis(const BigVec3& n) {
  int best = -1;
  double size = -1.0;
  for (int i = 0; i < 3; ++i) {
    std::int64_t e = 0;
    const BigFloat& c = component(n, i);
    if (c.is_zero()) continue;
    const double m = std::fabs(c.frexp(e));
    // Compare |c| by exponent first, then mantissa.
    const double key = static_cast<double>(e) + m;
    if (best < 0 || key > size) {
      best = i;
      size = key;
    }
  }
  return best < 0 ? 2 : best;
}

Result<Soup> make_soup(std::span<const Mesh> inputs) {
  Soup soup;
  soup.inputs = inputs.size();
  PointTable& welded = soup.index;
  std::size_t vertices = 0, triangles = 0;
  for (const Mesh& mesh : inputs) {
    vertices += mesh.vertices.size();
    triangles += mesh.triangles.size();
  }
  // Room for the point store's crossings too: the store takes this table over as it is.
  welded.reserve(store_room(vertices), soup.vertices);
  soup.vertices.reserve(vertices);
  soup.triangles.reserve(triangles);
  soup.input.reserve(triangles);
  soup.degenerate.reserve(triangles);
  std::vector<std::int32_t> remap;  // welded number of each vertex of the input at hand
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const Mesh& mesh = inputs[k];
    remap.resize(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Vec3 v = mesh.vertices[i];
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        return Error{.kind = ErrorKind::invalid_value,
                     .message = "input " + std::to_string(k) + ": vertex " + std::to_string(i) +
                                " is not finite"};
      }
      // + 0.0 turns -0 into +0: one key per position.
      const auto [id, fresh] =
          welded.try_emplace(Vec3{v.x + 0.0, v.y + 0.0, v.z + 0.0},
                             static_cast<std::int32_t>(soup.vertices.size()), soup.vertices);
      if (fresh) soup.vertices.push_back({v.x + 0.0, v.y + 0.0, v.z + 0.0});
      remap[i] = id;
    }
    const std::size_t first = soup.triangles.size();
    // Each triangle's welded corners and whether it is degenerate in one pass over the input (a
    // second pass over the soup read every corner again).
    for (const TriangleIndices& t : mesh.triangles) {
      for (const std::int32_t i : t) {
        if (i < 0 || static_cast<std::size_t>(i) >= mesh.vertices.size()) {
          return Error{.kind = ErrorKind::invalid_value,
                       .message = "input " + std::to_string(k) + ": vertex index " +
                                  std::to_string(i) + " out of range"};
        }
      }
      const TriangleIndices w = {remap[static_cast<std::size_t>(t[0])],
                                 remap[static_cast<std::size_t>(t[1])],
                                 remap[static_cast<std::size_t>(t[2])]};
      soup.triangles.push_back(w);
      soup.input.push_back(static_cast<std::int32_t>(k));
      const Vec3 a = soup.vertices[static_cast<std::size_t>(w[0])];
      const Vec3 b = soup.vertices[static_cast<std::size_t>(w[1])];
      const Vec3 c = soup.vertices[static_cast<std::size_t>(w[2])];
      // Zero area exactly when the three projections onto the coordinate planes have zero area.
      const bool degenerate = orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero &&
                              orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero &&
                              orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero;
      soup.degenerate.push_back(degenerate);
    }
    if (const Status closed = check_closed(soup, first, k); !closed) return closed.error();
  }
  // The linear (Morton) build at every size: the SAH's binned sweep of every triangle per level
  // was a quarter of a boolean of two spheres of 131k triangles and 15% of one of 2k, and the
  // looser tree costs the pairs and rays less than that. The tree's order numbers the crossing
  // points, which steers how merged coplanar faces are triangulated again: a different build
  // writes different (equally valid, the same solid) triangulations of merged faces.
  // The boxes from the corners (triangle_box), not kept.
  soup.tree = bvh::Bvh::morton(soup.triangles.size(),
                               [&soup](std::size_t t) { return triangle_box(soup, t); });
  return soup;
}

const BigVec3& Soup::normal(std::size_t t) const {
  if (normals_.size() != triangles.size()) normals_.resize(triangles.size());
  std::unique_ptr<BigVec3>& n = normals_[t];
  if (!n) {
    const TriangleIndices& v = triangles[t];
    n = std::make_unique<BigVec3>(exact_normal(vertices[static_cast<std::size_t>(v[0])],
                                               vertices[static_cast<std::size_t>(v[1])],
                                               vertices[static_cast<std::size_t>(v[2])]));
  }
  return *n;
}

Projection Soup::projection(std::size_t t) const {
  const TriangleIndices& v = triangles[t];
  if (const std::optional<Projection> p = filtered_projection(
          vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
          vertices[static_cast<std::size_t>(v[2])])) {
    return *p;
  }
  const BigVec3& n = normal(t);
  const int axis = dropped_axis(n);
  return {axis, component(n, axis).sign()};
}

}  // namespace contain::clip::solid
