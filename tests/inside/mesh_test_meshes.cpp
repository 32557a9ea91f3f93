#include "inside/mesh_test_meshes.h"

#include <array>

namespace contain::test {

Mesh grid_cube(double lo, double hi, int n) {
  Mesh m;
  const double step = (hi - lo) / n;
  // For each of the 6 faces: axis d fixed at lo or hi; (u, v) the other two axes in a right-handed
  // order so that u x v points along +d, and the face at lo is flipped.
  for (int d = 0; d < 3; ++d) {
    for (int side = 0; side < 2; ++side) {
      const int u = (d + 1) % 3, v = (d + 2) % 3;
      const auto base = static_cast<std::int32_t>(m.vertices.size());
      for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
          std::array<double, 3> p{};
          p[static_cast<std::size_t>(d)] = side ? hi : lo;
          p[static_cast<std::size_t>(u)] = i == n ? hi : lo + i * step;
          p[static_cast<std::size_t>(v)] = j == n ? hi : lo + j * step;
          m.vertices.push_back({p[0], p[1], p[2]});
        }
      }
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const std::int32_t a = base + j * (n + 1) + i, b = a + 1, c = a + (n + 1), e = c + 1;
          if (side) {
            m.triangles.push_back({a, b, e});
            m.triangles.push_back({a, e, c});
          } else {
            m.triangles.push_back({a, e, b});
            m.triangles.push_back({a, c, e});
          }
        }
      }
    }
  }
  // Weld the shared edges of the faces (exact equality of grid coordinates).
  std::vector<std::int32_t> remap(m.vertices.size());
  std::vector<Vec3> unique;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    std::size_t k = 0;
    while (k < unique.size() && !(unique[k] == m.vertices[i]))
      ++k;
    if (k == unique.size()) unique.push_back(m.vertices[i]);
    remap[i] = static_cast<std::int32_t>(k);
  }
  for (auto& t : m.triangles)
    for (auto& v : t)
      v = remap[static_cast<std::size_t>(v)];
  m.vertices = unique;
  return m;
}

Mesh octahedron(double r) {
  Mesh m;
  m.vertices = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

Mesh l_prism() {
  Mesh m;
  const Vec2 ring[6] = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  for (int level = 0; level < 2; ++level)
    for (const Vec2& p : ring)
      m.vertices.push_back({p.x, p.y, level * 2.0});
  // Bottom (z = 0, facing -z) and top as fans of two convex quads: (0 1 2 3) and (0 3 4 5).
  const int quads[2][4] = {{0, 1, 2, 3}, {0, 3, 4, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[2], q[1]});
    m.triangles.push_back({q[0], q[3], q[2]});
    m.triangles.push_back({q[0] + 6, q[1] + 6, q[2] + 6});
    m.triangles.push_back({q[0] + 6, q[2] + 6, q[3] + 6});
  }
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    m.triangles.push_back({i, j, j + 6});
    m.triangles.push_back({i, j + 6, i + 6});
  }
  return m;
}

Mesh scaled(Mesh mesh, double s) {
  for (Vec3& v : mesh.vertices)
    v = s * v;
  return mesh;
}

}  // namespace contain::test
