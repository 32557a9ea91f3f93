#include "collide/test_meshes.h"

#include <cmath>

namespace contain::test {

Mesh box_mesh(Vec3 lo, Vec3 hi) {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  }
  // Outward counter-clockwise faces of the cube with corners indexed by bits (x, y, z).
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

Transform translation(Vec3 t) {
  Transform x;
  x.t = t;
  return x;
}

Transform random_pose(std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> n(0.0, 1.0);
  double w = n(rng), x = n(rng), y = n(rng), z = n(rng);
  const double len = std::sqrt(w * w + x * x + y * y + z * z);
  w /= len, x /= len, y /= len, z /= len;
  Transform t;
  t.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
  std::uniform_real_distribution<double> u(-spread, spread);
  t.t = {u(rng), u(rng), u(rng)};
  return t;
}

}  // namespace contain::test
