#pragma once
/// \file
/// Point sets for the bounding-ball tests: random distributions and exactly degenerate sets.

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "contain/values/vec.h"

namespace contain::test {

inline std::vector<Vec3> uniform_cube(std::size_t n, std::mt19937_64& rng, double half = 1.0) {
  std::uniform_real_distribution<double> u(-half, half);
  std::vector<Vec3> out(n);
  for (Vec3& p : out)
    p = {u(rng), u(rng), u(rng)};
  return out;
}

inline std::vector<Vec3> uniform_ball(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out;
  while (out.size() < n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    if (squared_length(p) <= 1.0) out.push_back(p);
  }
  return out;
}

inline std::vector<Vec3> gaussian(std::size_t n, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  std::vector<Vec3> out(n);
  for (Vec3& p : out)
    p = {g(rng), g(rng), g(rng)};
  return out;
}

/// Gaussian directions normalised in floating point: within a few ulps of the unit sphere.
inline std::vector<Vec3> rounded_unit_sphere(std::size_t n, std::mt19937_64& rng) {
  std::vector<Vec3> out = gaussian(n, rng);
  for (Vec3& p : out)
    p = (1.0 / length(p)) * p;
  return out;
}

/// Every integer point with x^2 + y^2 + z^2 = r2: exactly cospherical, symmetric about 0.
inline std::vector<Vec3> integer_sphere(int r2) {
  std::vector<Vec3> out;
  const int r = static_cast<int>(std::sqrt(static_cast<double>(r2))) + 1;
  for (int x = -r; x <= r; ++x) {
    for (int y = -r; y <= r; ++y) {
      for (int z = -r; z <= r; ++z) {
        if (x * x + y * y + z * z == r2) out.push_back({double(x), double(y), double(z)});
      }
    }
  }
  return out;
}

/// Every integer point with x^2 + y^2 = r2: exactly cocircular.
inline std::vector<Vec2> integer_circle(int r2) {
  std::vector<Vec2> out;
  const int r = static_cast<int>(std::sqrt(static_cast<double>(r2))) + 1;
  for (int x = -r; x <= r; ++x) {
    for (int y = -r; y <= r; ++y) {
      if (x * x + y * y == r2) out.push_back({double(x), double(y)});
    }
  }
  return out;
}

}  // namespace contain::test
