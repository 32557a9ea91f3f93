#include "contain/inside/fast_winding_number.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "contain/bvh/triangle_boxes.h"
#include "contain/inside/winding_number_3d.h"

// Far field (Barill et al. 2018, order 1): the solid angle of a patch of total area vector N
// around c, seen from p far away, is N . (c - p) / |c - p|^3. Nodes are filled bottom up (the
// depth-first layout puts children after their parent, so a reverse sweep sees them first).

namespace contain::inside {

FastWindingNumber::FastWindingNumber(const Mesh& mesh, const FastWindingNumberOptions& options)
    : accuracy_(options.accuracy) {
  triangles_.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    triangles_.push_back(mesh.triangle(t));
  const std::vector<Box3> boxes = bvh::triangle_boxes(mesh);
  bvh_ = bvh::Bvh(boxes);
  const std::span<const bvh::Node> nodes = bvh_.nodes();
  dipoles_.assign(nodes.size(), {});
  std::vector<double> area(nodes.size(), 0.0);
  for (std::size_t n = nodes.size(); n-- > 0;) {
    const bvh::Node& node = nodes[n];
    Vec3 weighted{}, vector{};
    double total = 0.0;
    if (node.is_leaf()) {
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const Triangle3& t =
            triangles_[static_cast<std::size_t>(bvh_.items()[static_cast<std::size_t>(k)])];
        const Vec3 half_normal = 0.5 * t.normal();
        const double a = length(half_normal);
        vector = vector + half_normal;
        weighted = weighted + a * ((1.0 / 3.0) * (t.a + t.b + t.c));
        total += a;
      }
    } else {
      for (std::size_t child : {n + 1, static_cast<std::size_t>(node.first)}) {
        vector = vector + dipoles_[child].area_vector;
        weighted = weighted + area[child] * dipoles_[child].centre;
        total += area[child];
      }
    }
    area[n] = total;
    const Vec3 centre =
        total > 0.0 ? (1.0 / total) * weighted : 0.5 * node.box.min + 0.5 * node.box.max;
    double radius2 = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 q{(corner & 1) ? node.box.max.x : node.box.min.x,
                   (corner & 2) ? node.box.max.y : node.box.min.y,
                   (corner & 4) ? node.box.max.z : node.box.min.z};
      radius2 = std::max(radius2, squared_length(q - centre));
    }
    dipoles_[n] = {centre, vector, options.accuracy * options.accuracy * radius2};
  }
}

double FastWindingNumber::evaluate(Vec3 p) const {
  double sum = 0.0;
  (void)bvh_.traverse(
      [&](const bvh::Node& node, std::int32_t index) {
        const Dipole& d = dipoles_[static_cast<std::size_t>(index)];
        const Vec3 r = d.centre - p;
        const double r2 = squared_length(r);
        if (node.count != 1 && r2 > d.radius2) {
          sum += dot(d.area_vector, r) / (r2 * std::sqrt(r2));
          return false;
        }
        return true;
      },
      [&](std::int32_t item) {
        sum += solid_angle(triangles_[static_cast<std::size_t>(item)], p);
        return bvh::Visit::proceed;
      });
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace contain::inside
