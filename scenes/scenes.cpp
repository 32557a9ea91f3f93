#include "scenes/scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace contain::scenes {

Ring star_ring(int vertices, Vec2 center, double inner, double outer, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> radius(inner, outer);
  Ring ring;
  ring.reserve(static_cast<std::size_t>(vertices));
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / vertices;
    const double r = radius(rng);
    ring.push_back({center.x + r * std::cos(angle), center.y + r * std::sin(angle)});
  }
  return ring;
}

Ring flower_ring(int vertices, Vec2 center, double radius, double amplitude, int lobes) {
  Ring ring;
  ring.reserve(static_cast<std::size_t>(vertices));
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / vertices;
    const double r = radius * (1.0 + amplitude * std::sin(lobes * angle));
    ring.push_back({center.x + r * std::cos(angle), center.y + r * std::sin(angle)});
  }
  return ring;
}

Polygon demo_polygon() {
  Polygon polygon;
  polygon.rings.push_back(flower_ring(240, {0, 0}, 8.0, 0.3, 5));
  Ring star = star_ring(14, {-2.5, 0.5}, 0.8, 2.0, 7);
  std::reverse(star.begin(), star.end());
  polygon.rings.push_back(std::move(star));
  polygon.rings.push_back({{2, -3}, {2, -1}, {4, -1}, {4, -3}});  // clockwise square hole
  return polygon;
}

std::vector<Vec2> uniform_points(const Box2& box, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
  std::vector<Vec2> points(count);
  for (Vec2& p : points)
    p = {x(rng), y(rng)};
  return points;
}

std::vector<Vec3> uniform_points(const Box3& box, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y),
      z(box.min.z, box.max.z);
  std::vector<Vec3> points(count);
  for (Vec3& p : points)
    p = {x(rng), y(rng), z(rng)};
  return points;
}

std::vector<Transform> random_poses(std::size_t count, double reach, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(-reach, reach);
  std::vector<Transform> poses(count);
  for (Transform& t : poses) {
    double q[4] = {n(rng), n(rng), n(rng), n(rng)};
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q)
      x /= len;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    t.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    t.t = {u(rng), u(rng), u(rng)};
  }
  return poses;
}

Mesh uv_sphere(Vec3 center, double radius, int rings, int sides) {
  Mesh m;
  m.vertices.push_back(center + Vec3{0, 0, -radius});
  for (int i = 1; i < rings; ++i) {
    const double phi = std::numbers::pi * (static_cast<double>(i) / rings - 0.5);
    for (int j = 0; j < sides; ++j) {
      const double theta = 2 * std::numbers::pi * j / sides;
      m.vertices.push_back(center + radius * Vec3{std::cos(phi) * std::cos(theta),
                                                  std::cos(phi) * std::sin(theta), std::sin(phi)});
    }
  }
  m.vertices.push_back(center + Vec3{0, 0, radius});
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * sides + (j % sides); };
  const int top = static_cast<int>(m.vertices.size()) - 1;
  for (int j = 0; j < sides; ++j) {
    m.triangles.push_back({0, at(1, j + 1), at(1, j)});
    m.triangles.push_back({top, at(rings - 1, j), at(rings - 1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return m;
}

Mesh torus(double major, double minor, int rings, int sides) {
  Mesh mesh;
  for (int i = 0; i < rings; ++i) {
    const double u = 2.0 * std::numbers::pi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double v = 2.0 * std::numbers::pi * j / sides;
      const double r = major + minor * std::cos(v);
      mesh.vertices.push_back({r * std::cos(u), r * std::sin(u), minor * std::sin(v)});
    }
  }
  auto index = [&](int i, int j) { return ((i % rings) * sides) + (j % sides); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  return mesh;
}

Mesh joined(Mesh a, const Mesh& b) {
  const auto shift = static_cast<std::int32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (TriangleIndices t : b.triangles) {
    for (std::int32_t& v : t)
      v += shift;
    a.triangles.push_back(t);
  }
  return a;
}

Mesh box_mesh(const Box3& box) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back({(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                             (i & 4) ? box.max.z : box.min.z});
  }
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

std::vector<Segment2> uniform_segments(const Box2& box, std::size_t count, std::uint64_t seed) {
  const std::vector<Vec2> ends = uniform_points(box, 2 * count, seed);
  std::vector<Segment2> segments(count);
  for (std::size_t i = 0; i < count; ++i)
    segments[i] = {ends[2 * i], ends[2 * i + 1]};
  return segments;
}

std::vector<Segment3> uniform_segments(const Box3& box, std::size_t count, std::uint64_t seed) {
  const std::vector<Vec3> ends = uniform_points(box, 2 * count, seed);
  std::vector<Segment3> segments(count);
  for (std::size_t i = 0; i < count; ++i)
    segments[i] = {ends[2 * i], ends[2 * i + 1]};
  return segments;
}

std::vector<Vec3> grid_points(const Box2& box, int n, double z) {
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      points.push_back({box.min.x + (box.max.x - box.min.x) * i / (n - 1),
                        box.min.y + (box.max.y - box.min.y) * j / (n - 1), z});
    }
  }
  return points;
}

Mesh prism(Vec2 center, double radius, int sides, double z0, double z1) {
  Mesh mesh;
  for (const double z : {z0, z1}) {
    for (int i = 0; i < sides; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / sides;
      mesh.vertices.push_back(
          {center.x + radius * std::cos(angle), center.y + radius * std::sin(angle), z});
    }
  }
  const std::int32_t n = sides;
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t next = (i + 1) % n;
    if (i > 0 && next > 0) {
      mesh.triangles.push_back({0, next, i});          // bottom, seen from below
      mesh.triangles.push_back({n, n + i, n + next});  // top, seen from above
    }
    mesh.triangles.push_back({i, next, n + next});  // side, two triangles
    mesh.triangles.push_back({i, n + next, n + i});
  }
  return mesh;
}

Csg bracket_csg() {
  const Csg plate = Csg::leaf(Box3{{0, 0, 0}, {80, 40, 6}});
  const Csg wall = Csg::leaf(Box3{{0, 0, 6}, {80, 6, 40}});
  const Csg rib = Csg::intersection(
      {Csg::leaf(Box3{{37, 6, 6}, {43, 30, 30}}), Csg::leaf(Plane{0, -1, -1, 36})});  // y + z <= 36
  const Csg fillet = Csg::intersection({Csg::leaf(Box3{{60, 20, -1}, {81, 41, 7}}),
                                        Csg::leaf(Plane{1, 1, 0, -110})});  // x + y >= 110
  const Csg holes[] = {Csg::leaf(CsgMesh(prism({15, 25}, 4, 16, -1, 7))),
                       Csg::leaf(CsgMesh(prism({65, 25}, 4, 16, -1, 7)))};
  return Csg::difference(Csg::unite({plate, wall, rib}), Csg::unite({holes[0], holes[1], fillet}));
}

}  // namespace contain::scenes
