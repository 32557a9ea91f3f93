#pragma once
/// \file
/// Test-only generators of random regions and query points for point in polygon, biased towards
/// degeneracy: small integer coordinates (shared vertices, collinear and overlapping edges),
/// points on vertices, on edges and on the grid lines of an index.

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "contain/shapes/polygon.h"

namespace contain::test {

/// 1..max_rings rings of 3..max_vertices vertices with integer coordinates in [0, extent].
inline std::vector<Ring> random_integer_rings(std::mt19937_64& rng, int max_rings, int max_vertices,
                                              int extent) {
  std::uniform_int_distribution<int> ring_count(1, max_rings), vertex_count(3, max_vertices),
      coordinate(0, extent);
  std::vector<Ring> rings(static_cast<std::size_t>(ring_count(rng)));
  for (Ring& ring : rings) {
    const int n = vertex_count(rng);
    for (int i = 0; i < n; ++i) {
      ring.push_back({static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng))});
    }
  }
  return rings;
}

/// A star-shaped ring of n vertices around (cx, cy), radii in [0.3, 1] * scale, angles jittered.
inline Ring random_star(std::mt19937_64& rng, int n, double cx, double cy, double scale) {
  std::uniform_real_distribution<double> radius(0.3, 1.0), jitter(0.0, 0.9);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * 3.141592653589793 * (i + jitter(rng)) / n;
    const double r = scale * radius(rng);
    ring.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
  }
  return ring;
}

/// Points on and near the rings: every vertex, points rounded onto edges (a + t (b - a)), edge
/// midpoints, and the vertices nudged by one ulp.
inline std::vector<Vec2> points_near_rings(std::mt19937_64& rng, const std::vector<Ring>& rings,
                                           int per_edge) {
  std::uniform_real_distribution<double> t(0.0, 1.0);
  std::vector<Vec2> points;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      points.push_back(a);
      points.push_back({std::nextafter(a.x, 1e300), a.y});
      points.push_back({a.x, std::nextafter(a.y, -1e300)});
      points.push_back({0.5 * (a.x + b.x), 0.5 * (a.y + b.y)});
      for (int k = 0; k < per_edge; ++k) {
        const double s = t(rng);
        points.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
      }
    }
  }
  return points;
}

}  // namespace contain::test
