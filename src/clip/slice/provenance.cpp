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
#include <limits>
#include <optional>

#include "clip/slice/stages.h"
#include "contain/bvh/bvh.h"
#include "contain/predicates/orient2d.h"
#include "contain/values/max_abs.h"

namespace contain::clip::slice {

namespace {

struct Endpoint {
  Vec2 p;
  std::int32_t segment;
};
bool less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

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

class Matcher {
 public:
  explicit Matcher(std::span<const CrossingSegment> segments) : segments_(segments) {
    ends_.reserve(2 * segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      ends_.push_back({segments[i].from, static_cast<std::int32_t>(i)});
      ends_.push_back({segments[i].to, static_cast<std::int32_t>(i)});
    }
    std::sort(ends_.begin(), ends_.end(), [](const Endpoint& a, const Endpoint& b) {
      return less(a.p, b.p) || (a.p == b.p && a.segment < b.segment);
    });
  }

  std::int32_t triangle(Vec2 p, Vec2 q) {
    Score best;
    for (const Vec2 end : {p, q}) {
      auto it = std::lower_bound(ends_.begin(), ends_.end(), end,
                                 [](const Endpoint& e, Vec2 x) { return less(e.p, x); });
      for (; it != ends_.end() && it->p == end; ++it)
        consider(it->segment, p, q, best);
    }
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
  std::vector<Endpoint> ends_;
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
