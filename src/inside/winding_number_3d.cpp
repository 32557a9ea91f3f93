#include "contain/inside/winding_number_3d.h"

#include <cmath>
#include <numbers>

namespace contain::inside {

// tan(omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|), with a, b, c the
// vertices relative to p (Van Oosterom and Strackee 1983); atan2 picks the right branch.
double solid_angle(const Triangle3& t, Vec3 p) {
  const Vec3 a = t.a - p, b = t.b - p, c = t.c - p;
  const double la = length(a), lb = length(b), lc = length(c);
  const double numerator = dot(a, cross(b, c));
  const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

double generalized_winding_number(const Mesh& mesh, Vec3 p) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    sum += solid_angle(mesh.triangle(t), p);
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace contain::inside
