#include "distance/mesh_oracle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "contain/values/box.h"
#include "support/tri_tri_oracle.h"

namespace contain::test {

namespace {

Triangle3 triangle_of(const Mesh& mesh, std::size_t i) {
  const TriangleIndices& t = mesh.triangles[i];
  return {mesh.vertices[static_cast<std::size_t>(t[0])],
          mesh.vertices[static_cast<std::size_t>(t[1])],
          mesh.vertices[static_cast<std::size_t>(t[2])]};
}

Box3 box_of(const Triangle3& t) {
  Box3 b;
  for (const Vec3& v : {t.a, t.b, t.c})
    b.expand(v);
  return b;
}

// The same gap in doubles: only an order of visit (nearest boxes first, so that the exact gap
// skips most triangles), never a decision.
double rough_box_gap(Vec3 p, const Box3& b) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  const double dz = std::max({b.min.z - p.z, 0.0, p.z - b.max.z});
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

MeshOracleAnswer mesh_oracle(const Mesh& mesh, Vec3 p) {
  std::vector<std::pair<double, std::size_t>> order;
  std::vector<Box3> boxes;
  order.reserve(mesh.triangles.size());
  boxes.reserve(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    boxes.push_back(box_of(triangle_of(mesh, i)));
    order.emplace_back(rough_box_gap(p, boxes.back()), i);
  }
  std::sort(order.begin(), order.end());
  MeshOracleAnswer best;
  for (const auto& [rough, i] : order) {
    // A triangle whose box is exactly farther than the best cannot win or tie.
    if (best.triangle >= 0 && exact_squared_distance(p, boxes[i]) > best.squared_distance) continue;
    const ExactClosest3 c = exact_closest(p, triangle_of(mesh, i));
    const auto index = static_cast<std::int32_t>(i);
    if (best.triangle < 0 || c.squared_distance < best.squared_distance ||
        (c.squared_distance == best.squared_distance && index < best.triangle)) {
      best = {c.squared_distance, c.point, index};
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

mpq_class exact_triangle_pair(const Triangle3& s, const Triangle3& t) {
  if (exact_tri_tri_3d(s, t)) return 0;
  mpq_class best = exact_closest(s.a, t).squared_distance;
  for (const Vec3& v : {s.b, s.c})
    best = std::min(best, exact_closest(v, t).squared_distance);
  for (const Vec3& v : {t.a, t.b, t.c})
    best = std::min(best, exact_closest(v, s).squared_distance);
  const Segment3 es[3] = {{s.a, s.b}, {s.b, s.c}, {s.c, s.a}};
  const Segment3 et[3] = {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}};
  for (const Segment3& x : es)
    for (const Segment3& y : et)
      best = std::min(best, exact_squared_distance(x, y));
  return best;
}

mpq_class triangle_box_gap(const Triangle3& s, const Triangle3& t) {
  Box3 x, y;
  for (const Vec3& v : {s.a, s.b, s.c})
    x.expand(v);
  for (const Vec3& v : {t.a, t.b, t.c})
    y.expand(v);
  mpq_class sum = 0;
  const double lo1[3] = {x.min.x, x.min.y, x.min.z}, hi1[3] = {x.max.x, x.max.y, x.max.z};
  const double lo2[3] = {y.min.x, y.min.y, y.min.z}, hi2[3] = {y.max.x, y.max.y, y.max.z};
  for (int k = 0; k < 3; ++k) {
    mpq_class g = 0;
    if (lo1[k] > hi2[k]) g = mpq_class(lo1[k]) - mpq_class(hi2[k]);
    if (lo2[k] > hi1[k]) g = mpq_class(lo2[k]) - mpq_class(hi1[k]);
    sum += g * g;
  }
  return sum;
}

PairOracle pair_oracle(const Mesh& a, const Mesh& b) {
  PairOracle best;
  for (std::size_t i = 0; i < a.triangles.size(); ++i) {
    const auto& ta = a.triangles[i];
    const Triangle3 s{a.vertices[static_cast<std::size_t>(ta[0])],
                      a.vertices[static_cast<std::size_t>(ta[1])],
                      a.vertices[static_cast<std::size_t>(ta[2])]};
    for (std::size_t j = 0; j < b.triangles.size(); ++j) {
      const auto& tb = b.triangles[j];
      const Triangle3 t{b.vertices[static_cast<std::size_t>(tb[0])],
                        b.vertices[static_cast<std::size_t>(tb[1])],
                        b.vertices[static_cast<std::size_t>(tb[2])]};
      if (best.a >= 0 && triangle_box_gap(s, t) > best.d2) continue;
      const mpq_class d = exact_triangle_pair(s, t);
      if (best.a < 0 || d < best.d2) best = {d, static_cast<int>(i), static_cast<int>(j)};
    }
  }
  return best;
}

}  // namespace contain::test
