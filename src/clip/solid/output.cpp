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
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/validate.h"
#include "contain/core/union_find.h"

namespace contain::clip::solid {
namespace {

bool filled(Op op, const std::vector<int>& w) {
  if (w.empty()) return false;
  std::size_t count = 0;
  for (const int x : w)
    count += x > 0 ? 1 : 0;
  switch (op) {
    case Op::union_:
      return count > 0;
    case Op::intersection:
      return count == w.size();
    case Op::difference:
      return w[0] > 0 && count == 1;
    case Op::xor_:
      return count % 2 == 1;
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
  const int axis = dropped_axis(soup.normal(static_cast<std::size_t>(face.triangle)));
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

double signed_volume(const Mesh& mesh) {
  double six = 0.0;
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 a = mesh.vertex(t[0]), b = mesh.vertex(t[1]), c = mesh.vertex(t[2]);
    six += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
           a.z * (b.x * c.y - b.y * c.x);
  }
  return six / 6.0;
}

// Points merged into one vertex (rule solid-output): faces that lose a corner so are dropped,
// and two faces that become the same triangle in opposite directions cancel. What this leaves
// is checked.
using Representative = std::unordered_map<std::int32_t, std::int32_t>;

std::vector<std::array<std::int32_t, 3>> merge_coincident(
    const std::vector<std::array<std::int32_t, 3>>& faces, const Representative& rep) {
  std::map<std::array<std::int32_t, 3>, std::vector<std::size_t>> by_corners;
  std::vector<std::array<std::int32_t, 3>> merged;
  for (const auto& f : faces) {
    std::array<std::int32_t, 3> t = {rep.at(f[0]), rep.at(f[1]), rep.at(f[2])};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    merged.push_back(t);
  }
  // Cancel opposite pairs: key (a, b, c) with a smallest; its reverse is (a, c, b).
  std::vector<bool> gone(merged.size(), false);
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const auto& t = merged[i];
    const std::array<std::int32_t, 3> reverse = {t[0], t[2], t[1]};
    auto it = by_corners.find(reverse);
    if (it != by_corners.end() && !it->second.empty()) {
      gone[it->second.back()] = true;
      gone[i] = true;
      it->second.pop_back();
    } else {
      by_corners[t].push_back(i);
    }
  }
  std::vector<std::array<std::int32_t, 3>> out;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    if (!gone[i]) out.push_back(merged[i]);
  }
  return out;
}

// The written point of each point of `faces`: at level < 0, the first point with the same
// nearest doubles (the written mesh could not tell them apart); at level >= 0, the first point
// (by number) of its cluster: points whose nearest doubles are within ulp(scale) 2^level of each
// other in every coordinate are joined, transitively (a crude snap rounding).
Representative representatives(const std::vector<std::array<std::int32_t, 3>>& faces,
                               const PointStore& store, int level, double scale) {
  std::vector<std::int32_t> ids;
  for (const auto& f : faces)
    ids.insert(ids.end(), f.begin(), f.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  Representative rep;
  if (level < 0) {
    for (const std::int32_t i : ids)
      rep[i] = store.representative(i);
    return rep;
  }
  const double h =
      std::ldexp(std::nextafter(scale, std::numeric_limits<double>::infinity()) - scale, level);
  std::vector<std::size_t> by_x(ids.size());
  for (std::size_t k = 0; k < by_x.size(); ++k)
    by_x[k] = k;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return store.rounded(ids[a]).x < store.rounded(ids[b]).x;
  });
  UnionFind<std::size_t> near(ids.size());  // the smallest index (so the smallest id) leads
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Vec3 p = store.rounded(ids[by_x[k]]);
    for (std::size_t m = k + 1; m < by_x.size(); ++m) {
      const Vec3 q = store.rounded(ids[by_x[m]]);
      if (q.x - p.x > h) break;
      if (std::fabs(q.y - p.y) <= h && std::fabs(q.z - p.z) <= h) near.unite(by_x[k], by_x[m]);
    }
  }
  for (std::size_t k = 0; k < ids.size(); ++k)
    rep[ids[k]] = ids[near.find(k)];
  return rep;
}

// The faces' mesh with points merged by `rep`, sheets kept apart.
Mesh written_mesh(const std::vector<std::array<std::int32_t, 3>>& kept, const Representative& rep,
                  const PointStore& store) {
  const Sheets sheets = separate_sheets(merge_coincident(kept, rep), store);
  Mesh mesh;
  for (const std::int32_t p : sheets.points)
    mesh.vertices.push_back(store.rounded(p));
  for (const auto& t : sheets.faces)
    mesh.triangles.push_back({t[0], t[1], t[2]});
  return mesh;
}

}  // namespace

Result<MeshBooleanResult> write_result(const Soup& soup, const Refinement& refinement,
                                       const std::vector<TriangleWork>& work,
                                       const std::vector<FaceLabel>& labels,
                                       const PointStore& store, Op op) {
  std::vector<std::array<std::int32_t, 3>> kept;
  for (std::size_t f = 0; f < refinement.faces.size(); ++f) {
    const RefinedFace& face = refinement.faces[f];
    const bool front = filled(op, labels[f].front), back = filled(op, labels[f].back);
    if (front == back) continue;
    if (!owned(soup, face, work[static_cast<std::size_t>(face.triangle)], store)) continue;
    kept.push_back(back ? face.v : std::array<std::int32_t, 3>{face.v[0], face.v[2], face.v[1]});
  }
  double scale = 0.0;
  for (const Vec3 v : soup.vertices) {
    scale = std::max({scale, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  scale = std::max(scale, std::numeric_limits<double>::min());
  // Grid sides up to 2^20 ulps of the largest coordinate (about 2.3e-10 of it: within the 1e-9
  // that ../shared/spec/cli.md allows), each tried only when the previous one failed the check.
  Status valid = Ok{};
  for (int level = -1; level <= 20; level += 3) {
    const Representative rep = representatives(kept, store, level, scale);
    MeshBooleanResult result;
    result.mesh = written_mesh(kept, rep, store);
    valid = check_written(result.mesh);
    if (!valid) continue;
    for (const auto& [i, r] : rep) {
      const Vec3 a = store.rounded(i), b = store.rounded(r);
      result.moved += (a.x != b.x || a.y != b.y || a.z != b.z) ? 1 : 0;
    }
    result.shells = count_shells(result.mesh);
    result.volume = signed_volume(result.mesh);
    return result;
  }
  return valid.error();
}

}  // namespace contain::clip::solid
