#include "distance/mesh_oracle.h"

#include <cmath>
#include <cstdio>

namespace contain::test {

MeshOracleAnswer mesh_oracle(const Mesh& mesh, Vec3 p) {
  MeshOracleAnswer best;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const TriangleIndices& t = mesh.triangles[i];
    const Triangle3 tri{mesh.vertices[static_cast<std::size_t>(t[0])],
                        mesh.vertices[static_cast<std::size_t>(t[1])],
                        mesh.vertices[static_cast<std::size_t>(t[2])]};
    const ExactClosest3 c = exact_closest(p, tri);
    if (best.triangle < 0 || c.squared_distance < best.squared_distance) {
      best = {c.squared_distance, c.point, static_cast<std::int32_t>(i)};
    }
  }
  return best;
}

std::string hex3(Vec3 p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p.x, p.y, p.z);
  return buf;
}

std::string compare_with_oracle(const distance::Closest3& got, const MeshOracleAnswer& want,
                                bool check_point) {
  const double d = nearest_double_sqrt(want.squared_distance);
  std::string out;
  if (std::fabs(got.distance) != d) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "distance %a want %a; ", got.distance, d);
    out += buf;
  }
  if (got.feature != want.triangle) {
    out +=
        "triangle " + std::to_string(got.feature) + " want " + std::to_string(want.triangle) + "; ";
  }
  if (check_point) {
    const Vec3 q{nearest_double(want.point.x), nearest_double(want.point.y),
                 nearest_double(want.point.z)};
    if (!(got.point == q)) out += "point " + hex3(got.point) + " want " + hex3(q) + "; ";
  }
  return out;
}

}  // namespace contain::test
