#pragma once
// Intersection and difference skip the far edges of their larger operand. Private to the boolean
// engine.
//
// Far edges (rule clip-far-edges, docs/robustness.md). Every face kept by an intersection has
// w_B != 0, so it lies inside the box of B, and w_A matters there only; likewise a difference
// keeps faces with w_A != 0, inside the box of A. So the operand with the most edges may be
// replaced by any set of closed paths with the same winding numbers on a box R (the other
// operand's box, widened by a margin of 2^-20 of the largest coordinate): its edges whose boxes
// meet R are kept bit for bit, and each run of the others, from p to q, is replaced by an
// axis-parallel step from p away from R to a frame outside all input, a walk along the frame,
// full turns of the frame until the winding number around R agrees with the run's, and a step
// back to q. The winding numbers around R are counted exactly (a ray from a corner of R upward
// meets the run only strictly above R, decided by comparisons of input doubles). The new points
// are exact doubles and lie outside R, the margin keeps their hot pixels far from the faces that
// are kept, and only edges near the other operand are noded: a small polygon against a large one
// costs O(n) comparisons plus the arrangement of the edges near it.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <span>
#include <vector>

#include "clip/boolean/arrangement.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"

namespace contain::clip::detail {

/// The size of an operand: its non-degenerate edges, their box and largest coordinate.
struct Operand {
  Box2 box;
  std::size_t edges = 0;
  double magnitude = 0.0;
};

[[nodiscard]] Operand measure(std::span<const Ring> rings);

/// The segment a b meets the closed box.
[[nodiscard]] inline bool meets(const Box2& box, Vec2 a, Vec2 b) {
  return !(std::max(a.x, b.x) < box.min.x || std::min(a.x, b.x) > box.max.x ||
           std::max(a.y, b.y) < box.min.y || std::min(a.y, b.y) > box.max.y);
}

/// `outer` contains `inner` (closed).
[[nodiscard]] inline bool covers(const Box2& outer, const Box2& inner) {
  return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
         inner.max.y <= outer.max.y;
}

// Replaces the far edges of rings by frame paths (see the file comment).
class FarEdges {
 public:
  FarEdges(const Box2& r, const Box2& frame) : r_(r), f_(frame) {
    corner_[0] = {f_.max.x, f_.min.y};
    corner_[1] = {f_.max.x, f_.max.y};
    corner_[2] = {f_.min.x, f_.max.y};
    corner_[3] = {f_.min.x, f_.min.y};
  }

  // Appends the reduced rings; false when a winding count could not be decided (never expected).
  bool add(std::span<const Ring> rings, SegmentLabel label, ArrangementInput& in) {
    std::vector<Vec2> copy;
    std::vector<char> keep;
    for (const Ring& ring : rings) {
      continues_ = false;
      // The ring without repeated points (a copy only when it has some).
      bool clean = ring.size() >= 2 && ring.back() != ring.front();
      for (std::size_t i = 1; clean && i < ring.size(); ++i)
        clean = ring[i] != ring[i - 1];
      std::span<const Vec2> v(ring);
      if (!clean) {
        copy.clear();
        for (const Vec2 p : ring) {
          if (copy.empty() || copy.back() != p) copy.push_back(p);
        }
        while (copy.size() > 1 && copy.back() == copy.front())
          copy.pop_back();
        v = copy;
      }
      const std::size_t n = v.size();
      if (n < 2) continue;
      keep.resize(n);
      std::size_t kept = 0;
      for (std::size_t i = 0; i < n; ++i) {
        keep[i] = meets(r_, v[i], v[i + 1 < n ? i + 1 : 0]) ? 1 : 0;
        kept += keep[i];
      }
      if (kept == n) {
        for (std::size_t i = 0; i < n; ++i)
          push(in, v[i], v[i + 1 < n ? i + 1 : 0], label);
        continue;
      }
      if (kept == 0) {
        int w = 0;
        for (std::size_t i = 0; i < n; ++i)
          w += turn(v[i], v[i + 1 < n ? i + 1 : 0]);
        if (!ok_) return false;
        loops(in, corner_[3], w, label);
        continue;
      }
      // Runs of far edges, in ring order; a run through the end of the ring goes last.
      std::size_t start = 0;
      while (!keep[start])
        ++start;
      // Edges start, start+1, ... (mod n) are visited once; kept edges are emitted in ring order
      // except the ones before `start`, which are all far.
      std::size_t i = start;
      std::size_t visited = 0;
      while (visited < n) {
        if (keep[i]) {
          push(in, v[i], v[i + 1 < n ? i + 1 : 0], label);
          i = i + 1 < n ? i + 1 : 0;
          ++visited;
          continue;
        }
        const Vec2 p = v[i];
        int w = 0;
        while (visited < n && !keep[i]) {
          w += turn(v[i], v[i + 1 < n ? i + 1 : 0]);
          i = i + 1 < n ? i + 1 : 0;
          ++visited;
        }
        bridge(in, p, v[i], w, label);
        if (!ok_) return false;
      }
    }
    return ok_;
  }

 private:
  // +1 when a -> b crosses the ray up from (r.min.x, r.max.y) from right to left, -1 left to right.
  int turn(Vec2 a, Vec2 b) {
    const double cx = r_.min.x;
    if ((a.x < cx) == (b.x < cx)) return 0;
    if (std::min(a.y, b.y) > r_.max.y) return a.x < cx ? -1 : 1;
    if (std::max(a.y, b.y) < r_.min.y) return 0;
    ok_ = false;
    return 0;
  }
  // Consecutive pushes of one ring continue one path.
  void push(ArrangementInput& in, Vec2 a, Vec2 b, SegmentLabel label) {
    if (a == b) return;
    in.push(a, b, label, continues_);
    continues_ = true;
  }
  // The side of the frame (0 bottom, 1 right, 2 top, 3 left) an outward step from p reaches.
  [[nodiscard]] int side(Vec2 p) const {
    if (p.x < r_.min.x) return 3;
    if (p.x > r_.max.x) return 1;
    return p.y < r_.min.y ? 0 : 2;
  }
  [[nodiscard]] Vec2 exit(Vec2 p, int s) const {
    switch (s) {
      case 0:
        return {p.x, f_.min.y};
      case 1:
        return {f_.max.x, p.y};
      case 2:
        return {p.x, f_.max.y};
      default:
        return {f_.min.x, p.y};
    }
  }
  // q is on side s ahead of p (counter-clockwise) or equal to it.
  static bool ahead(Vec2 p, Vec2 q, int s) {
    switch (s) {
      case 0:
        return q.x >= p.x;
      case 1:
        return q.y >= p.y;
      case 2:
        return q.x <= p.x;
      default:
        return q.y <= p.y;
    }
  }
  void step(ArrangementInput& in, Vec2& at, Vec2 to, SegmentLabel label, int& w) {
    w += turn(at, to);
    push(in, at, to, label);
    at = to;
  }
  // |turns| full turns of the frame (counter-clockwise when positive) from `at`, a point inside
  // a side of the frame or the corner (min.x, min.y).
  void loops(ArrangementInput& in, Vec2 at, int turns, SegmentLabel label) {
    int s = side_of_frame_point(at);
    const Vec2 start = at;
    int w = 0;
    for (int k = 0; k < std::abs(turns); ++k) {
      if (turns > 0) {
        for (int j = 0; j < 4; ++j)
          step(in, at, corner_[(s + j) % 4], label, w);
      } else {
        for (int j = 0; j < 4; ++j)
          step(in, at, corner_[(s + 3 - j) % 4], label, w);
      }
      step(in, at, start, label, w);
    }
    if (w != turns) ok_ = false;
  }
  // The side a frame point lies on, counter-clockwise order; a corner counts as the side it ends.
  [[nodiscard]] int side_of_frame_point(Vec2 p) const {
    if (p.y == f_.min.y && p.x != f_.min.x) return 0;
    if (p.x == f_.max.x && p.y != f_.min.y) return 1;
    if (p.y == f_.max.y && p.x != f_.max.x) return 2;
    return 3;
  }
  void bridge(ArrangementInput& in, Vec2 p, Vec2 q, int w_run, SegmentLabel label) {
    int w = 0;
    Vec2 at = p;
    const int sp = side(p), sq = side(q);
    const Vec2 pe = exit(p, sp), qe = exit(q, sq);
    step(in, at, pe, label, w);
    int s = sp;
    if (!(s == sq && ahead(pe, qe, s))) {
      do {
        step(in, at, corner_[s], label, w);
        s = (s + 1) % 4;
      } while (s != sq);
    }
    step(in, at, qe, label, w);
    const int missing = w_run - w;
    if (missing != 0) loops(in, qe, missing, label);
    at = qe;
    step(in, at, q, label, w);
  }

  Box2 r_, f_;
  Vec2 corner_[4];
  bool ok_ = true;
  bool continues_ = false;
};

}  // namespace contain::clip::detail
