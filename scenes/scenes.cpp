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

}  // namespace contain::scenes
