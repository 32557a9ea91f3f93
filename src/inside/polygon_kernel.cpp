#include "inside/polygon_kernel.h"

#include <algorithm>

namespace contain::inside::detail {

namespace {

struct Direction {
  Vec2 to;     // a point along the direction from p
  int delta;   // +1 outgoing edge, -1 incoming
  bool upper;  // angle in [0, pi)
};

}  // namespace

Location classify_on_edges(Vec2 p, int winding, std::span<const Edge> incident, Fill fill) {
  std::vector<Direction> dirs;
  dirs.reserve(2 * incident.size());
  auto add = [&](Vec2 to, int delta) {
    const bool upper = to.y > p.y || (to.y == p.y && to.x > p.x);
    dirs.push_back({to, delta, upper});
  };
  for (const Edge& e : incident) {
    if (e.a == e.b) continue;
    if (e.a != p) add(e.a, -1);
    if (e.b != p) add(e.b, +1);
  }
  if (dirs.empty()) return is_filled(fill, winding) ? Location::inside : Location::outside;

  // Counter-clockwise from the +x direction (included): upper half first, then orient2d.
  std::sort(dirs.begin(), dirs.end(), [&](const Direction& u, const Direction& v) {
    if (u.upper != v.upper) return u.upper;
    return predicates::orient2d(p, u.to, v.to) == Sign::positive;
  });
  // Merge equal directions (overlapping collinear edges): the sectors between them are empty.
  std::vector<int> deltas;
  deltas.reserve(dirs.size());
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const bool same = i > 0 && dirs[i].upper == dirs[i - 1].upper &&
                      predicates::orient2d(p, dirs[i - 1].to, dirs[i].to) == Sign::zero;
    if (same) {
      deltas.back() += dirs[i].delta;
    } else {
      deltas.push_back(dirs[i].delta);
    }
  }
  // p+ lies just after the direction +x if there is one (it sorts first), else just before the
  // first direction (in the sector that wraps around).
  const bool first_is_east = dirs.front().upper && dirs.front().to.y == p.y;
  const int groups = static_cast<int>(deltas.size());
  const int start = first_is_east ? 0 : -1;
  bool any_filled = is_filled(fill, winding);
  bool any_empty = !any_filled;
  int w = winding;
  for (int g = start + 1; g < start + groups; ++g) {
    w += deltas[static_cast<std::size_t>(g)];
    if (is_filled(fill, w)) {
      any_filled = true;
    } else {
      any_empty = true;
    }
  }
  if (any_filled && any_empty) return Location::boundary;
  return any_filled ? Location::inside : Location::outside;
}

void RayAccumulator::add_ring(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n == 0) return;
  Vec2 a = ring[n - 1];
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 b = ring[i];
    bool incident = false;
    winding_ += ray_crossing(a, b, p_, incident);
    if (incident) incident_.push_back({a, b});
    a = b;
  }
}

Location RayAccumulator::location(Fill fill) const {
  if (incident_.empty()) return is_filled(fill, winding_) ? Location::inside : Location::outside;
  return classify_on_edges(p_, winding_, incident_, fill);
}

}  // namespace contain::inside::detail
