// Stage 5 and 6 of the mesh boolean: the refined faces on the result's boundary, oriented with
// the result behind them, one face for each set of coinciding faces, the exact points rounded to
// their nearest doubles, and the written mesh checked exactly (rule solid-output in
// docs/robustness.md).
//
// A face is on the boundary when the operation's answer differs on its two sides. Faces of
// coplanar triangles that overlap lie in the overlap region of each of them, and each of them
// has the same labels there (the rays count every coinciding face): the face of the triangle
// with the lowest number among those covering it is written, the others are not.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/snap.h"
#include "contain/core/union_find.h"
#include "contain/predicates/rounded_volume.h"

namespace contain::clip::solid {
namespace {

bool filled(Op op, const SideLabel& side, std::size_t inputs) {
  if (inputs == 0) return false;
  switch (op) {
    case Op::union_:
      return side.filled > 0;
    case Op::intersection:
      return side.filled == inputs;
    case Op::difference:
      return side.first_filled && side.filled == 1;
    case Op::xor_:
      return side.filled % 2 == 1;
  }
  return false;
}

// The exact centroid of face f lies strictly inside coplanar triangle u.
bool covered_by(const Soup& soup, std::int32_t u, const ExactPoint& c, int axis) {
  const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(u)];
  const ExactPoint a = exact_point(soup.vertices[static_cast<std::size_t>(v[0])]);
  const ExactPoint b = exact_point(soup.vertices[static_cast<std::size_t>(v[1])]);
  const ExactPoint d = exact_point(soup.vertices[static_cast<std::size_t>(v[2])]);
  const Sign turn = orient2d_dropped(a, b, d, axis);
  return turn != Sign::zero && orient2d_dropped(a, b, c, axis) == turn &&
         orient2d_dropped(b, d, c, axis) == turn && orient2d_dropped(d, a, c, axis) == turn;
}

bool owned(const Soup& soup, const RefinedFace& face, const TriangleWork& work,
           const PointStore& store) {
  bool any_lower = false;
  for (const std::int32_t u : work.coplanar)
    any_lower = any_lower || u < face.triangle;
  if (!any_lower) return true;
  const ExactPoint c =
      centroid(store.point(face.v[0]), store.point(face.v[1]), store.point(face.v[2]));
  const int axis = soup.projection(static_cast<std::size_t>(face.triangle)).axis;
  for (const std::int32_t u : work.coplanar) {
    if (u < face.triangle && covered_by(soup, u, c, axis)) return false;
  }
  return true;
}

std::size_t count_shells(const Mesh& mesh) {
  UnionFind<std::size_t> sets(mesh.vertices.size());
  for (const TriangleIndices& t : mesh.triangles) {
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]));
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[2]));
  }
  std::size_t shells = 0;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    shells += sets.find(i) == i ? 1 : 0;
  return shells;
}

// The written positions that are not the nearest doubles of an exact point of the result,
// counted once each: the faces' points marked by the first point of their doubles in the store
// (flat arrays and the store's own table, not hash sets of nodes).
std::size_t moved_count(const Faces& faces, const PointStore& store,
                        const std::vector<Vec3>& written) {
  std::vector<char> used(store.size(), 0), nearest(store.size(), 0);
  for (const auto& f : faces) {
    for (const std::int32_t i : f)
      used[static_cast<std::size_t>(i)] = 1;
  }
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i] != 0)
      nearest[static_cast<std::size_t>(store.representative(static_cast<std::int32_t>(i)))] = 1;
  }
  std::vector<Vec3> other;
  for (const Vec3 v : written) {
    const std::int32_t first = store.first_rounded_to(v);
    if (first < 0 || nearest[static_cast<std::size_t>(first)] == 0) other.push_back(v);
  }
  std::sort(other.begin(), other.end(), [](Vec3 a, Vec3 b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  const auto same = [](Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  return static_cast<std::size_t>(std::unique(other.begin(), other.end(), same) - other.begin());
}

}  // namespace

BoundaryFaces boundary_faces(const Soup& soup, const Refinement& refinement, const PairWork& work,
                             const FaceLabels& labels, const PointStore& store, Op op) {
  // The answer on each side of each patch once (a face shares its patch's labels): 1 front
  // filled, 2 back filled.
  std::vector<std::uint8_t> sides(labels.of_patch.size());
  for (std::size_t p = 0; p < sides.size(); ++p) {
    const FaceLabel& label = labels.of_patch[p];
    sides[p] = static_cast<std::uint8_t>((filled(op, label.front, soup.inputs) ? 1U : 0U) |
                                         (filled(op, label.back, soup.inputs) ? 2U : 0U));
  }
  BoundaryFaces out;
  for (std::size_t f = 0; f < refinement.faces.size(); ++f) {
    const RefinedFace& face = refinement.faces[f];
    const std::uint8_t side = sides[labels.patch[f]];
    if (side == 0 || side == 3) continue;  // the same answer on both sides
    const bool back = side == 2;
    if (!owned(soup, face, work[static_cast<std::size_t>(face.triangle)], store)) continue;
    out.faces.push_back(back ? face.v
                             : std::array<std::int32_t, 3>{face.v[0], face.v[2], face.v[1]});
    out.triangle.push_back(face.triangle);
  }
  return out;
}

Result<MeshBooleanResult> write_result(const Soup& soup, const BoundaryFaces& boundary,
                                       PointStore& store, Op op) {
  double scale = 0.0;
  for (const Vec3 v : soup.vertices) {
    scale = std::max({scale, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  scale = std::max(scale, std::numeric_limits<double>::min());
  const Faces faces = merge_coplanar(soup, boundary, store);
  std::size_t rounds = 0;
  bool one_shell = false;  // as the check of the written mesh found it
  Result<Mesh> mesh = snap_round(faces, store, scale, &rounds, &one_shell);
  bool inputs_snapped = false;
  if (!mesh && mesh.error().kind == ErrorKind::degenerate) {
    mesh = snap_inputs(soup, op, scale, faces, store, mesh.error());
    inputs_snapped = true;
    one_shell = false;
  }
  if (!mesh) return mesh.error();
  // Written positions that are not the nearest doubles of an exact point of the result. When the
  // first written mesh passed (no round, inputs not snapped), each vertex is the nearest doubles
  // of a face point's representative, the first point of the store with those doubles, which
  // moved_count finds marked: none moved, and the lookup of every vertex is skipped.
  MeshBooleanResult result;
  result.moved = rounds == 0 && !inputs_snapped ? 0 : moved_count(faces, store, mesh->vertices);
  result.mesh = std::move(*mesh);
  // The check's union-find of the same vertex numbers found one shell: count_shells would too.
  result.shells = one_shell ? 1 : count_shells(result.mesh);
  result.volume = predicates::rounded_signed_volume(result.mesh.vertices, result.mesh.triangles);
  return result;
}

}  // namespace contain::clip::solid
