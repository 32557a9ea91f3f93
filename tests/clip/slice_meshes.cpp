#include "clip/slice_meshes.h"

#include <cmath>
#include <numbers>

#include "scenes/scenes.h"

namespace contain::test {

Mesh voxel_mesh(int n, const std::function<bool(int, int, int)>& filled) {
  const auto in = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n && filled(i, j, k);
  };
  Mesh m;
  // A face of the voxel (i, j, k) on the side `dir` of axis `a`, counter-clockwise from outside.
  const auto face = [&](int i, int j, int k, int a, int dir) {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    Vec3 corner[4];
    for (int q = 0; q < 4; ++q) {
      double p[3] = {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)};
      p[a] += dir > 0 ? 1 : 0;
      const int db = (q == 1 || q == 2) ? 1 : 0;
      const int dc = (q >= 2) ? 1 : 0;
      p[b] += db;
      p[c] += dc;
      corner[q] = {p[0], p[1], p[2]};
    }
    const auto base = static_cast<std::int32_t>(m.vertices.size());
    for (const Vec3& v : corner)
      m.vertices.push_back(v);
    // (b, c, a) is right-handed: corners 0,1,2,3 run counter-clockwise seen from +a.
    if (dir > 0) {
      m.triangles.push_back({base, base + 1, base + 2});
      m.triangles.push_back({base, base + 2, base + 3});
    } else {
      m.triangles.push_back({base, base + 2, base + 1});
      m.triangles.push_back({base, base + 3, base + 2});
    }
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        if (!in(i, j, k)) continue;
        const int at[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          for (int dir : {-1, 1}) {
            int o[3] = {at[0], at[1], at[2]};
            o[a] += dir;
            if (!in(o[0], o[1], o[2])) face(i, j, k, a, dir);
          }
      }
  return m;
}

Mesh rotated_cube(Vec3 center, double h, double a, double b) {
  Mesh m = scenes::box_mesh(Box3{{-h, -h, -h}, {h, h, h}});
  for (Vec3& v : m.vertices) {
    const Vec3 r{v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a), v.z};
    v = center +
        Vec3{r.x, r.y * std::cos(b) - r.z * std::sin(b), r.y * std::sin(b) + r.z * std::cos(b)};
  }
  return m;
}

Mesh joined(const Mesh& a, const Mesh& b, bool flip_second) {
  Mesh m = a;
  const auto base = static_cast<std::int32_t>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (TriangleIndices t : b.triangles) {
    for (std::int32_t& i : t)
      i += base;
    if (flip_second) std::swap(t[1], t[2]);
    m.triangles.push_back(t);
  }
  return m;
}

}  // namespace contain::test
