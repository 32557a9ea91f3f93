// The exact check of the written mesh. Crossings are found with the pair stage itself on the
// written doubles (welded by position, so sheets kept apart at one position share corners): any
// constraint between triangles in different planes is a meeting beyond their shared corners;
// triangles in one plane are tested in 2D with exact orient2d (closed edges against closed
// triangles, the edges through a shared corner left out, as collide::self_intersections does).

#include "clip/solid/validate.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;

struct Flat {
  int axis;
  [[nodiscard]] Vec2 operator()(Vec3 v) const {
    const double c[3] = {v.x, v.y, v.z};
    return {c[(axis + 1) % 3], c[(axis + 2) % 3]};
  }
};

bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  return orient2d(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x &&
         p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = to_int(orient2d(a, b, c)), o2 = to_int(orient2d(a, b, d));
  const int o3 = to_int(orient2d(c, d, a)), o4 = to_int(orient2d(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

bool in_triangle(const std::array<Vec2, 3>& t, Vec2 p) {
  const int o = to_int(orient2d(t[0], t[1], t[2]));
  for (int i = 0; i < 3; ++i) {
    if (to_int(
            orient2d(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)], p)) *
            o <
        0) {
      return false;
    }
  }
  return true;
}

bool segment_meets_triangle(Vec2 a, Vec2 b, const std::array<Vec2, 3>& t) {
  if (in_triangle(t, a) || in_triangle(t, b)) return true;
  for (int i = 0; i < 3; ++i) {
    if (segments_meet(a, b, t[static_cast<std::size_t>(i)],
                      t[static_cast<std::size_t>((i + 1) % 3)])) {
      return true;
    }
  }
  return false;
}

// Coplanar triangles t, u of the soup meet beyond their shared corners.
bool coplanar_meet(const Soup& soup, std::int32_t t, std::int32_t u) {
  const Flat flat{dropped_axis(soup.normal(static_cast<std::size_t>(t)))};
  const TriangleIndices& vt = soup.triangles[static_cast<std::size_t>(t)];
  const TriangleIndices& vu = soup.triangles[static_cast<std::size_t>(u)];
  std::array<Vec2, 3> a{}, b{};
  int shared = 0, at = -1, bt = -1;
  for (std::size_t i = 0; i < 3; ++i) {
    a[i] = flat(soup.vertices[static_cast<std::size_t>(vt[i])]);
    b[i] = flat(soup.vertices[static_cast<std::size_t>(vu[i])]);
    for (std::size_t j = 0; j < 3; ++j) {
      if (vt[i] == vu[j]) {
        ++shared;
        at = static_cast<int>(i);
        bt = static_cast<int>(j);
      }
    }
  }
  if (shared >= 2) return true;  // folded onto each other or repeated (the pair stage kept it)
  if (shared == 1) {
    const auto far = [](const std::array<Vec2, 3>& x, int k) {
      return std::pair{x[static_cast<std::size_t>((k + 1) % 3)],
                       x[static_cast<std::size_t>((k + 2) % 3)]};
    };
    const auto [a1, a2] = far(a, at);
    const auto [b1, b2] = far(b, bt);
    return segment_meets_triangle(a1, a2, b) || segment_meets_triangle(b1, b2, a);
  }
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(a[static_cast<std::size_t>(i)],
                               a[static_cast<std::size_t>((i + 1) % 3)], b)) {
      return true;
    }
  }
  return in_triangle(a, b[0]);
}

Status failure(const std::string& what) {
  return Error{.kind = ErrorKind::degenerate,
               .message = "the result rounded to doubles is not valid (" + what + ")"};
}

}  // namespace

Status check_written(const Mesh& mesh) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::size_t k = 0; k < 3; ++k)
      ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) {
      return failure("an edge is not matched by exactly one opposite edge");
    }
  }
  const Result<Soup> soup = make_soup(std::span<const Mesh>(&mesh, 1));
  if (!soup) return failure(soup.error().message);
  for (const bool flat : soup->degenerate) {
    if (flat) return failure("a triangle has zero area");
  }
  PointStore store;
  for (const Vec3 v : soup->vertices)
    (void)store.add(v);
  const std::vector<TriangleWork> work = intersect_pairs(*soup, store);
  for (std::size_t t = 0; t < work.size(); ++t) {
    for (const Constraint& c : work[t].constraints) {
      if (c.edge == no_edge) return failure("two triangles cross");
    }
    for (const std::int32_t u : work[t].coplanar) {
      if (coplanar_meet(*soup, static_cast<std::int32_t>(t), u)) {
        return failure("two triangles in one plane overlap");
      }
    }
  }
  return Ok{};
}

}  // namespace contain::clip::solid
