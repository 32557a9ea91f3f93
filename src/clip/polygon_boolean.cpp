// Polygon booleans on the arrangement (boolean_arrangement.cpp), with one shortcut.
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

#include "contain/clip/polygon_boolean.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "clip/boolean_arrangement.h"

namespace contain::clip {
namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = std::numeric_limits<double>::infinity();
  double x1 = -std::numeric_limits<double>::infinity();
  double y1 = -std::numeric_limits<double>::infinity();
  void add(Vec2 p) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  [[nodiscard]] bool empty() const { return !(x0 <= x1 && y0 <= y1); }
  [[nodiscard]] bool meets(Vec2 a, Vec2 b) const {
    return !(std::max(a.x, b.x) < x0 || std::min(a.x, b.x) > x1 || std::max(a.y, b.y) < y0 ||
             std::min(a.y, b.y) > y1);
  }
  [[nodiscard]] bool covers(const Box& o) const {
    return x0 <= o.x0 && y0 <= o.y0 && o.x1 <= x1 && o.y1 <= y1;
  }
};

struct Operand {
  Box box;
  std::size_t edges = 0;
  double magnitude = 0.0;
};

Operand measure(std::span<const Ring> rings) {
  Operand o;
  for (const Ring& ring : rings) {
    // Every point of a ring with an edge is the start of an edge or equal to one.
    const std::size_t n = ring.size();
    if (n == 0) continue;
    std::size_t edges = 0;
    Box box;
    Vec2 a = ring[n - 1];
    for (const Vec2 b : ring) {
      edges += a != b ? 1 : 0;
      box.add(b);
      a = b;
    }
    if (edges == 0) continue;
    o.edges += edges;
    o.box.add({box.x0, box.y0});
    o.box.add({box.x1, box.y1});
    o.magnitude = std::max(
        {o.magnitude, std::fabs(box.x0), std::fabs(box.x1), std::fabs(box.y0), std::fabs(box.y1)});
  }
  return o;
}

// Replaces the far edges of rings by frame paths (see the file comment).
class FarEdges {
 public:
  FarEdges(const Box& r, const Box& frame) : r_(r), f_(frame) {
    corner_[0] = {f_.x1, f_.y0};
    corner_[1] = {f_.x1, f_.y1};
    corner_[2] = {f_.x0, f_.y1};
    corner_[3] = {f_.x0, f_.y0};
  }

  // Appends the reduced rings; false when a winding count could not be decided (never expected).
  bool add(std::span<const Ring> rings, detail::SegmentLabel label, detail::ArrangementInput& in) {
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
        keep[i] = r_.meets(v[i], v[i + 1 < n ? i + 1 : 0]) ? 1 : 0;
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
  // +1 when a -> b crosses the ray up from (r.x0, r.y1) from right to left, -1 left to right.
  int turn(Vec2 a, Vec2 b) {
    const double cx = r_.x0;
    if ((a.x < cx) == (b.x < cx)) return 0;
    if (std::min(a.y, b.y) > r_.y1) return a.x < cx ? -1 : 1;
    if (std::max(a.y, b.y) < r_.y0) return 0;
    ok_ = false;
    return 0;
  }
  // Consecutive pushes of one ring continue one path.
  void push(detail::ArrangementInput& in, Vec2 a, Vec2 b, detail::SegmentLabel label) {
    if (a == b) return;
    in.push(a, b, label, continues_);
    continues_ = true;
  }
  // The side of the frame (0 bottom, 1 right, 2 top, 3 left) an outward step from p reaches.
  [[nodiscard]] int side(Vec2 p) const {
    if (p.x < r_.x0) return 3;
    if (p.x > r_.x1) return 1;
    return p.y < r_.y0 ? 0 : 2;
  }
  [[nodiscard]] Vec2 exit(Vec2 p, int s) const {
    switch (s) {
      case 0:
        return {p.x, f_.y0};
      case 1:
        return {f_.x1, p.y};
      case 2:
        return {p.x, f_.y1};
      default:
        return {f_.x0, p.y};
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
  void step(detail::ArrangementInput& in, Vec2& at, Vec2 to, detail::SegmentLabel label, int& w) {
    w += turn(at, to);
    push(in, at, to, label);
    at = to;
  }
  // |turns| full turns of the frame (counter-clockwise when positive) from `at`, a point inside
  // a side of the frame or the corner (x0, y0).
  void loops(detail::ArrangementInput& in, Vec2 at, int turns, detail::SegmentLabel label) {
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
    if (p.y == f_.y0 && p.x != f_.x0) return 0;
    if (p.x == f_.x1 && p.y != f_.y0) return 1;
    if (p.y == f_.y1 && p.x != f_.x1) return 2;
    return 3;
  }
  void bridge(detail::ArrangementInput& in, Vec2 p, Vec2 q, int w_run, detail::SegmentLabel label) {
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

  Box r_, f_;
  Vec2 corner_[4];
  bool ok_ = true;
  bool continues_ = false;
};

bool keep_face(Op op, Fill fill, int wa, int wb) {
  const bool in_a = is_filled(fill, wa), in_b = is_filled(fill, wb);
  switch (op) {
    case Op::intersection:
      return in_a && in_b;
    case Op::union_:
      return in_a || in_b;
    case Op::difference:
      return in_a && !in_b;
    case Op::xor_:
      return in_a != in_b;
  }
  return false;
}

}  // namespace

MultiPolygon polygon_boolean(std::span<const Ring> a, std::span<const Ring> b,
                             const PolygonBooleanOptions& options, PolygonBooleanStats* stats) {
  const Fill fill = options.fill;
  const Op op = options.op;
  detail::ArrangementInput input;
  bool reduced = false;
  if (op == Op::intersection || op == Op::difference) {
    const Operand oa = measure(a), ob = measure(b);
    input.reserve(oa.edges + ob.edges + 64);
    const double magnitude = std::max(oa.magnitude, ob.magnitude);
    if (oa.edges == 0 || (op == Op::intersection && ob.edges == 0)) {
      if (stats != nullptr) *stats = {};
      return {};
    }
    // Faces with w != 0 lie inside the operand's box: an intersection of boxes without interior
    // has no such face.
    if (op == Op::intersection && ob.edges > 0 &&
        !(std::max(oa.box.x0, ob.box.x0) < std::min(oa.box.x1, ob.box.x1) &&
          std::max(oa.box.y0, ob.box.y0) < std::min(oa.box.y1, ob.box.y1))) {
      if (stats != nullptr) *stats = {};
      return {};
    }
    // The operand to reduce, and the box R it must stay right on.
    const bool reduce_a = op == Op::intersection && oa.edges > ob.edges;
    const Operand& big = reduce_a ? oa : ob;
    const Operand& small = reduce_a ? ob : oa;
    if (big.edges > 0 && magnitude > 0.0) {
      const double margin = std::ldexp(1.0, std::ilogb(magnitude) - 20);
      Box r = small.box;
      r.x0 -= margin;
      r.y0 -= margin;
      r.x1 += margin;
      r.y1 += margin;
      if (!r.covers(big.box)) {
        Box frame;
        frame.x0 = std::min({oa.box.x0, ob.box.x0, r.x0}) - margin;
        frame.y0 = std::min({oa.box.y0, ob.box.y0, r.y0}) - margin;
        frame.x1 = std::max({oa.box.x1, ob.box.x1, r.x1}) + margin;
        frame.y1 = std::max({oa.box.y1, ob.box.y1, r.y1}) + margin;
        const bool finite = std::isfinite(frame.x0) && std::isfinite(frame.y0) &&
                            std::isfinite(frame.x1) && std::isfinite(frame.y1);
        FarEdges far(r, frame);
        input.magnitude = magnitude;
        if (!finite) {
          reduced = false;
        } else if (reduce_a) {
          reduced = far.add(a, {.a = 1, .b = 0}, input);
          if (reduced) input.add_rings(b, {.a = 0, .b = 1});
        } else {
          input.add_rings(a, {.a = 1, .b = 0});
          reduced = far.add(b, {.a = 0, .b = 1}, input);
        }
        if (!reduced) input = {};
      }
    }
  }
  if (!reduced) {
    input.add_rings(a, {.a = 1, .b = 0});
    input.add_rings(b, {.a = 0, .b = 1});
  }
  const detail::Arrangement arrangement(input);
  if (stats != nullptr) {
    stats->input_edges = static_cast<std::int64_t>(input.segments.size());
    stats->crossings = arrangement.crossings;
    stats->noding_rounds = arrangement.rounds;
    stats->graph_edges = arrangement.edges;
    stats->converged = arrangement.converged;
  }
  return arrangement.extract([fill, op](int wa, int wb) { return keep_face(op, fill, wa, wb); });
}

MultiPolygon polygon_boolean(const MultiPolygon& a, const MultiPolygon& b,
                             const PolygonBooleanOptions& options) {
  const std::vector<Ring> ra = a.all_rings(), rb = b.all_rings();
  return polygon_boolean(ra, rb, options);
}

MultiPolygon polygon_boolean(const Polygon& a, const Polygon& b,
                             const PolygonBooleanOptions& options) {
  return polygon_boolean(a.rings, b.rings, options);
}

}  // namespace contain::clip
