#include "clip/solid/solid_oracle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "contain/collide/self_intersections.h"
#include "contain/predicates/closest_feature.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

mpq_class orient_yz(const QVec3& a, const QVec3& b, const QVec3& p) {
  return (b.y - a.y) * (p.z - a.z) - (b.z - a.z) * (p.y - a.y);
}

}  // namespace

std::optional<int> exact_winding(const Mesh& mesh, Vec3 point) {
  const QVec3 p = exact(point);
  int w = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    // Speed only (comparisons of doubles, exact): a triangle wholly behind the ray's start or
    // whose (y, z) box misses the ray's line neither holds p nor meets the ray.
    if (point.x > std::max({tri.a.x, tri.b.x, tri.c.x}) ||
        point.y < std::min({tri.a.y, tri.b.y, tri.c.y}) ||
        point.y > std::max({tri.a.y, tri.b.y, tri.c.y}) ||
        point.z < std::min({tri.a.z, tri.b.z, tri.c.z}) ||
        point.z > std::max({tri.a.z, tri.b.z, tri.c.z})) {
      continue;
    }
    const QVec3 a = exact(tri.a), b = exact(tri.b), c = exact(tri.c);
    const QVec3 n = qcross(qsub(b, a), qsub(c, a));
    const Sign s = sign_of(qdot(n, qsub(p, a)));
    const Sign nx = sign_of(n.x);
    if (qzero(n)) continue;  // bounds nothing
    const std::array<Sign, 3> e = {sign_of(orient_yz(a, b, p)), sign_of(orient_yz(b, c, p)),
                                   sign_of(orient_yz(c, a, p))};
    if (nx == Sign::zero) {
      // Parallel to the ray: only a point on it matters (then the sample is on the surface or
      // the ray runs in the triangle's plane).
      if (s == Sign::zero) return std::nullopt;
      continue;
    }
    const bool all_in = e[0] == nx && e[1] == nx && e[2] == nx;
    const bool touching = (e[0] == Sign::zero || e[1] == Sign::zero || e[2] == Sign::zero) &&
                          to_int(e[0]) * to_int(nx) >= 0 && to_int(e[1]) * to_int(nx) >= 0 &&
                          to_int(e[2]) * to_int(nx) >= 0;
    if (touching) {
      if (s == Sign::zero || s == -nx) return std::nullopt;  // on it, or the ray meets an edge
      continue;
    }
    if (!all_in) continue;
    if (s == Sign::zero) return std::nullopt;
    if (s == -nx) w += to_int(nx);
  }
  return w;
}

// The shells (triangles joined by shared vertex numbers) of a mesh whose triangles meet only at
// shared corners or edges: each is a closed surface, and the winding number is 0 or 1 off the
// surface exactly when each shell has positive volume and the other shells' winding number 0 at
// its vertices, or negative volume and 1 there. Asked with GMP: exact volumes, and the exact
// +x-ray winding number of the other shells at a vertex of the shell whose position no other
// shell uses (the next such vertex when the ray meets an edge; undecided shells pass).
bool inside_out_shell(const Mesh& mesh) {
  std::vector<std::size_t> root(mesh.vertices.size());
  for (std::size_t i = 0; i < root.size(); ++i)
    root[i] = i;
  const auto find = [&](std::size_t x) {
    while (root[x] != x)
      x = root[x] = root[root[x]];
    return x;
  };
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::size_t k = 1; k < 3; ++k)
      root[find(static_cast<std::size_t>(t[k]))] = find(static_cast<std::size_t>(t[0]));
  }
  std::map<std::size_t, Mesh> shells;
  std::map<std::tuple<double, double, double>, std::set<std::size_t>> users;
  for (const TriangleIndices& t : mesh.triangles) {
    const std::size_t s = find(static_cast<std::size_t>(t[0]));
    shells[s].vertices = mesh.vertices;
    shells[s].triangles.push_back(t);
    for (const std::int32_t v : t) {
      const Vec3 p = mesh.vertex(v);
      users[{p.x + 0.0, p.y + 0.0, p.z + 0.0}].insert(s);
    }
  }
  for (const auto& [s, shell] : shells) {
    const int volume = sgn(exact_volume(shell));
    if (volume == 0) return true;
    Mesh others;
    others.vertices = mesh.vertices;
    for (const TriangleIndices& t : mesh.triangles) {
      if (find(static_cast<std::size_t>(t[0])) != s) others.triangles.push_back(t);
    }
    for (const TriangleIndices& t : shell.triangles) {
      const Vec3 p = mesh.vertex(t[0]);
      if (users[{p.x + 0.0, p.y + 0.0, p.z + 0.0}].size() != 1) continue;
      const std::optional<int> w = exact_winding(others, p);
      if (!w) continue;
      if (*w != (volume < 0 ? 1 : 0)) return true;
      break;
    }
  }
  return false;
}

std::string invalid_reason(const Mesh& mesh) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::size_t k = 0; k < 3; ++k)
      ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto it = directed.find({edge.second, edge.first});
    if (count != 1 || it == directed.end() || it->second != 1) return "unmatched edge";
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    const QVec3 a = exact(tri.a);
    if (qzero(qcross(qsub(exact(tri.b), a), qsub(exact(tri.c), a)))) return "zero-area triangle";
  }
  if (!collide::self_intersections(mesh, {.limit = 1}).empty()) return "triangles cross";
  return inside_out_shell(mesh) ? "a shell inside out or nested in its own direction" : "";
}

bool in_result(clip::Op op, std::span<const int> windings) {
  std::size_t count = 0;
  for (const int w : windings)
    count += w > 0 ? 1 : 0;
  switch (op) {
    case clip::Op::union_:
      return count > 0;
    case clip::Op::intersection:
      return !windings.empty() && count == windings.size();
    case clip::Op::difference:
      return !windings.empty() && windings[0] > 0 && count == 1;
    case clip::Op::xor_:
      return count % 2 == 1;
  }
  return false;
}

Mesh box_mesh(Vec3 lo, Vec3 hi) {
  return scenes::box_mesh(Box3{lo, hi});
}

Mesh tetrahedron(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (exact_orient3d(a, b, c, d) == Sign::positive) std::swap(b, c);
  Mesh m{{a, b, c, d}, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}}};
  return m;
}

Mesh icosphere(int levels, double radius, Vec3 center) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<TriangleIndices> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  const auto unit = [](Vec3 p) {
    const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    return Vec3{p.x / l, p.y / l, p.z / l};
  };
  for (Vec3& p : v)
    p = unit(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> mid;
    const auto middle = [&](std::int32_t a, std::int32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = mid.try_emplace(key, static_cast<std::int32_t>(v.size()));
      if (fresh) {
        const Vec3 p = v[static_cast<std::size_t>(a)], q = v[static_cast<std::size_t>(b)];
        v.push_back(unit({(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2}));
      }
      return it->second;
    };
    std::vector<TriangleIndices> next;
    for (const TriangleIndices& t : f) {
      const std::int32_t a = middle(t[0], t[1]), b = middle(t[1], t[2]), c = middle(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  Mesh m;
  for (const Vec3 p : v) {
    m.vertices.push_back(
        {center.x + radius * p.x, center.y + radius * p.y, center.z + radius * p.z});
  }
  m.triangles = std::move(f);
  return m;
}

Mesh reversed(Mesh mesh) {
  for (TriangleIndices& t : mesh.triangles)
    std::swap(t[1], t[2]);
  return mesh;
}

Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const auto offset = static_cast<std::int32_t>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const TriangleIndices& t : b.triangles)
    m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return m;
}

clip::solid::Soup raw_soup(const std::vector<Vec3>& vertices,
                           const std::vector<TriangleIndices>& triangles) {
  clip::solid::Soup soup;
  soup.inputs = 1;
  soup.vertices = vertices;
  soup.triangles = triangles;
  soup.input.assign(triangles.size(), 0);
  for (const TriangleIndices& t : triangles) {
    const Vec3 a = vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = vertices[static_cast<std::size_t>(t[2])];
    const bool flat = predicates::collinear(a, b, c);
    soup.degenerate.push_back(flat);
    Box3 box;
    if (!flat) {
      box.expand(a);
      box.expand(b);
      box.expand(c);
    }
    soup.boxes.push_back(box);
  }
  soup.tree = bvh::Bvh(soup.boxes);
  return soup;
}

}  // namespace contain::test
