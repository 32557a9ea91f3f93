// Stage 5 of slicing: the mesh triangle under each edge of the section.
//
// Faces in the plane add no segment to either side's curve, so every output edge lies along the
// segment of some triangle: the boolean keeps input vertices bit for bit and adds only crossing
// points of two segments (rounded) and points snapped within a pixel of a few ulps. An edge is
// first matched exactly (both ends on a segment that has one of them as an endpoint: exact
// orient2d and box tests); an edge with a new point at each end (a piece in the middle of a
// segment, or a snapped one) takes the candidate segment nearest to both its ends, found in a
// box hierarchy of the segments built only when such an edge occurs.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "clip/slice/stages.h"
#include "contain/bvh/bvh.h"
#include "contain/predicates/orient2d.h"
#include "contain/values/max_abs.h"

namespace contain::clip::slice {

namespace {

bool in_box(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
bool on_segment(const CrossingSegment& s, Vec2 p) {
  // An end of the segment, the common case (the engine keeps input vertices), needs no orient2d
  // (whose exact stage a zero determinant always reaches).
  if (p == s.from || p == s.to) return true;
  return in_box(s.from, s.to, p) && predicates::orient2d(s.from, s.to, p) == Sign::zero;
}

// Distance from p to the closed segment a-b, in floating point (a choice among candidates, not
// a topological decision).
double distance_to(const CrossingSegment& s, Vec2 p) {
  const Vec2 d = s.to - s.from;
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? ((p.x - s.from.x) * d.x + (p.y - s.from.y) * d.y) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 q = s.from + t * d;
  return std::hypot(p.x - q.x, p.y - q.y);
}

// The order of preference among candidates: on the segment exactly, then nearest, then along the
// segment's direction, then the lowest triangle.
struct Score {
  bool exact = false;
  double distance = std::numeric_limits<double>::infinity();
  bool along = false;
  std::int32_t triangle = std::numeric_limits<std::int32_t>::max();
  [[nodiscard]] bool better_than(const Score& o) const {
    if (exact != o.exact) return exact;
    if (!exact && distance != o.distance) return distance < o.distance;
    if (along != o.along) return along;
    return triangle < o.triangle;
  }
};
// The score of segment s for the edge p -> q, or nothing when it cannot beat `best`.
std::optional<Score> score(const CrossingSegment& s, Vec2 p, Vec2 q, const Score& best) {
  Score out;
  out.exact = on_segment(s, p) && on_segment(s, q);
  if (!out.exact && best.exact) return std::nullopt;
  if (!out.exact) out.distance = std::max(distance_to(s, p), distance_to(s, q));
  const Vec2 e = q - p;
  const Vec2 d = s.to - s.from;
  out.along = e.x * d.x + e.y * d.y > 0;
  out.triangle = s.triangle;
  return out;
}

// The segments by endpoint: open addressing on the point's bits (+0 and -0 made one), each slot
// the head of a list of segment ends. Built in O(k) per plane where sorting the 2k ends cost a
// tenth of slicing 10,000 planes.
class EndIndex {
 public:
  explicit EndIndex(std::span<const CrossingSegment> segments) {
    std::size_t size = 16;
    while (size < 4 * segments.size())
      size *= 2;
    slots_.assign(size, Slot{});
    next_.resize(2 * segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      link(segments[i].from, static_cast<std::int32_t>(2 * i));
      link(segments[i].to, static_cast<std::int32_t>(2 * i + 1));
    }
  }
  // Calls f(segment) for each end of a segment at p.
  template <class F>
  void each_at(Vec2 p, F&& f) const {
    for (std::int32_t e = slots_[find(p)].head; e >= 0; e = next_[static_cast<std::size_t>(e)])
      f(e >> 1);
  }

 private:
  struct Slot {
    Vec2 p;
    std::int32_t head = -1;
  };
  static std::uint64_t bits(double x) {
    const double y = x + 0.0;  // -0 + 0 is +0: equal doubles, equal bits
    std::uint64_t out = 0;
    std::memcpy(&out, &y, sizeof out);
    return out;
  }
  std::size_t find(Vec2 p) const {
    const std::size_t mask = slots_.size() - 1;
    const std::uint64_t h =
        (bits(p.x) * 0x9E3779B97F4A7C15ULL) ^ (bits(p.y) * 0xC2B2AE3D27D4EB4FULL);
    for (std::size_t i = (h >> 20) & mask;; i = (i + 1) & mask) {
      if (slots_[i].head < 0 || slots_[i].p == p) return i;
    }
  }
  void link(Vec2 p, std::int32_t end) {
    Slot& slot = slots_[find(p)];
    slot.p = p;
    next_[static_cast<std::size_t>(end)] = slot.head;
    slot.head = end;
  }
  std::vector<Slot> slots_;
  std::vector<std::int32_t> next_;
};

class Matcher {
 public:
  explicit Matcher(std::span<const CrossingSegment> segments)
      : segments_(segments), ends_(segments) {}

  // The candidates are the segments with an end at p or q (the engine keeps input vertices),
  // then, when none holds the edge exactly, the segments near it; the best by `Score`, whose
  // order does not depend on the order of the candidates.
  std::int32_t triangle(Vec2 p, Vec2 q) {
    Score best;
    for (const Vec2 end : {p, q})
      ends_.each_at(end, [&](std::int32_t i) { consider(i, p, q, best); });
    if (!best.exact) near(p, q, best);
    return best.triangle == std::numeric_limits<std::int32_t>::max() ? -1 : best.triangle;
  }

 private:
  void consider(std::int32_t i, Vec2 p, Vec2 q, Score& best) const {
    const std::optional<Score> s = score(segments_[static_cast<std::size_t>(i)], p, q, best);
    if (s && s->better_than(best)) best = *s;
  }

  // Segments whose boxes come within a few ulps of the edge's box (a snapped or rounded point
  // is within 2 pixel radii of its segment); all segments if none does.
  void near(Vec2 p, Vec2 q, Score& best) {
    if (!tree_) build();
    const double pad = 16 * std::numeric_limits<double>::epsilon() * scale_;
    const Box3 box{{std::min(p.x, q.x) - pad, std::min(p.y, q.y) - pad, 0.0},
                   {std::max(p.x, q.x) + pad, std::max(p.y, q.y) + pad, 0.0}};
    bool any = false;
    (void)tree_->traverse(
        [&](const bvh::Node& node, std::int32_t) { return overlaps(node.box, box); },
        [&](std::int32_t i) {
          any = true;
          consider(i, p, q, best);
          return bvh::Visit::proceed;
        });
    if (any) return;
    for (std::size_t i = 0; i < segments_.size(); ++i)
      consider(static_cast<std::int32_t>(i), p, q, best);
  }

  static bool overlaps(const Box3& a, const Box3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
  }

  void build() {
    std::vector<Box3> boxes;
    boxes.reserve(segments_.size());
    for (const CrossingSegment& s : segments_) {
      Box3 b;
      b.expand(Vec3{s.from.x, s.from.y, 0.0});
      b.expand(Vec3{s.to.x, s.to.y, 0.0});
      boxes.push_back(b);
      scale_ = std::max({scale_, max_abs(s.from), max_abs(s.to)});
    }
    tree_.emplace(boxes);
  }

  std::span<const CrossingSegment> segments_;
  EndIndex ends_;
  std::optional<bvh::Bvh> tree_;
  double scale_ = 0.0;
};

}  // namespace

std::vector<std::vector<std::int32_t>> edge_triangles(const MultiPolygon& region,
                                                      std::span<const CrossingSegment> segments) {
  Matcher matcher(segments);
  std::vector<std::vector<std::int32_t>> out;
  for (const Polygon& polygon : region.polygons) {
    for (const Ring& ring : polygon.rings) {
      std::vector<std::int32_t>& edges = out.emplace_back();
      edges.reserve(ring.size());
      for (std::size_t i = 0; i < ring.size(); ++i)
        edges.push_back(matcher.triangle(ring[i], ring[(i + 1) % ring.size()]));
    }
  }
  return out;
}

}  // namespace contain::clip::slice
