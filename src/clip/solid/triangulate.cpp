// The constrained triangulation of one refined triangle: incremental insertion of the points
// (each splits the triangle it lies in, or the two triangles of the edge it lies on), then each
// constraint piece recovered by flipping the edges that cross it (Sloan, "A fast algorithm for
// generating constrained Delaunay triangulations", 1993, section 3: an edge crossing the piece is
// flipped when its quadrilateral is strictly convex, and put back otherwise; this ends with the
// piece an edge). Every decision is the exact orientation of implicit points (rule
// solid-exact-points). Small inputs (a triangle's own constraints): linear scans.

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::clip::solid {
namespace {

using Tri = std::array<std::int32_t, 3>;

class Triangulation {
 public:
  Triangulation(const Tri& corners, const PointStore& store, int axis, Sign sense)
      : store_(store), axis_(axis), sense_(sense) {
    tris_.push_back(corners);
  }

  [[nodiscard]] int orient(std::int32_t a, std::int32_t b, std::int32_t c) const {
    return to_int(sense_) *
           to_int(orient2d_dropped(store_.point(a), store_.point(b), store_.point(c), axis_));
  }

  void insert(std::int32_t p) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Tri t = tris_[i];
      const std::array<int, 3> s = {orient(t[0], t[1], p), orient(t[1], t[2], p),
                                    orient(t[2], t[0], p)};
      if (s[0] < 0 || s[1] < 0 || s[2] < 0) continue;
      if (s[0] > 0 && s[1] > 0 && s[2] > 0) {
        tris_[i] = {t[0], t[1], p};
        tris_.push_back({t[1], t[2], p});
        tris_.push_back({t[2], t[0], p});
        return;
      }
      const int k = s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2);  // p on edge k (not a corner: unique ids)
      const std::int32_t a = t[static_cast<std::size_t>(k)],
                         b = t[static_cast<std::size_t>((k + 1) % 3)],
                         c = t[static_cast<std::size_t>((k + 2) % 3)];
      tris_[i] = {a, p, c};
      tris_.push_back({p, b, c});
      const auto [j, d] = find(b, a);
      if (j >= 0) {
        tris_[static_cast<std::size_t>(j)] = {b, p, d};
        tris_.push_back({p, a, d});
      }
      return;
    }
  }

  void enforce(std::int32_t a, std::int32_t b) {
    if (find(a, b).first >= 0 || find(b, a).first >= 0) return;
    std::deque<std::pair<std::int32_t, std::int32_t>> queue;
    for (const Tri& t : tris_) {
      for (int k = 0; k < 3; ++k) {
        const std::int32_t u = t[static_cast<std::size_t>(k)],
                           v = t[static_cast<std::size_t>((k + 1) % 3)];
        if (u < v && crosses(a, b, u, v)) queue.emplace_back(u, v);
      }
    }
    while (!queue.empty()) {
      const auto [u, v] = queue.front();
      queue.pop_front();
      const auto [i, x] = find(u, v);
      const auto [j, y] = find(v, u);
      if (orient(x, y, u) * orient(x, y, v) < 0) {
        tris_[static_cast<std::size_t>(i)] = {u, y, x};
        tris_[static_cast<std::size_t>(j)] = {y, v, x};
        if (crosses(a, b, x, y)) queue.emplace_back(x, y);
      } else {
        queue.emplace_back(u, v);
      }
    }
  }

  [[nodiscard]] std::vector<Tri> take() { return std::move(tris_); }

 private:
  // The triangle holding the directed edge u -> v and its third corner, or (-1, -1).
  [[nodiscard]] std::pair<std::int32_t, std::int32_t> find(std::int32_t u, std::int32_t v) const {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Tri& t = tris_[i];
      for (int k = 0; k < 3; ++k) {
        if (t[static_cast<std::size_t>(k)] == u && t[static_cast<std::size_t>((k + 1) % 3)] == v) {
          return {static_cast<std::int32_t>(i), t[static_cast<std::size_t>((k + 2) % 3)]};
        }
      }
    }
    return {-1, -1};
  }

  // The open segments a b and u v cross at one point inside both.
  [[nodiscard]] bool crosses(std::int32_t a, std::int32_t b, std::int32_t u, std::int32_t v) const {
    if (u == a || u == b || v == a || v == b) return false;
    return orient(a, b, u) * orient(a, b, v) < 0 && orient(u, v, a) * orient(u, v, b) < 0;
  }

  const PointStore& store_;
  int axis_;
  Sign sense_;
  std::vector<Tri> tris_;
};

}  // namespace

std::vector<std::array<std::int32_t, 3>> triangulate(
    const std::array<std::int32_t, 3>& corners, std::span<const std::int32_t> points,
    std::span<const std::array<std::int32_t, 2>> pieces, const PointStore& store, int axis,
    Sign sense) {
  Triangulation tri(corners, store, axis, sense);
  for (const std::int32_t p : points) {
    if (p != corners[0] && p != corners[1] && p != corners[2]) tri.insert(p);
  }
  for (const auto& piece : pieces)
    tri.enforce(piece[0], piece[1]);
  return tri.take();
}

}  // namespace contain::clip::solid
