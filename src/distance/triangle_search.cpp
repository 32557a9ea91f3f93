#include "distance/triangle_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/bvh/triangle_boxes.h"

namespace contain::distance::detail {

namespace {

constexpr double kEps = 0x1p-53;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Ericson's closest point on a triangle (Real-Time Collision Detection, 5.1.5), in doubles: only
// a guess, bounded afterwards. Its parameters along the edges lie in [0, 1] as computed (each is
// d / (d - d') with d >= 0 >= d'), and inside the face they are nonnegative with a sum within a
// few ulps of 1.
inline Vec3 approximate_closest(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return a + v * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return b + w * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  if (!(v >= 0 && w >= 0 && v + w <= 1.5)) return a;  // NaN or a sliver's noise: any point will do
  return a + ab * v + ac * w;
}

// (p - v) . w minus a bound on its rounding error: a lower bound of the exact value with w
// taken as exact doubles. Each monomial passes one difference, one product and two sums:
// gamma_4 < 5 eps of the permanent; 8 eps leaves room for the rounding of the bound.
inline double separation_lower(Vec3 p, Vec3 v, Vec3 w) {
  const Vec3 d = p - v;
  const double s = (d.x * w.x + d.y * w.y) + d.z * w.z;
  const double perm = (std::fabs(d.x * w.x) + std::fabs(d.y * w.y)) + std::fabs(d.z * w.z);
  return s - 8 * kEps * perm;
}

}  // namespace

double triangle_slack(double max_abs) {
  // A computed point a + ab v + ac w (or a vertex, or on an edge) lies within
  // 4 eps (|a| + |ab| + |ac|) <= 20 eps M per coordinate of the exact a + v (b - a) + w (c - a)
  // for the computed v, w, and that point lies within 4 eps (|ab| + |ac|) <= 16 eps M of the
  // triangle (v + w may pass 1 by a few ulps): delta <= sqrt(3) * 36 eps M < 64 eps M. Then
  // (|u| + delta)^2 <= (1 + t) |u|^2 + (1 + 1 / t) delta^2 with t = 2^-20. The square may
  // underflow: plus one subnormal unit.
  const double delta = 64 * kEps * max_abs;
  return delta * delta * (1 + 0x1p20) * (1 + 0x1p-40) + std::numeric_limits<double>::denorm_min();
}

void triangle_bounds(Vec3 p, const Triangle3& t, double slack, double& lo, double& hi) {
  const Vec3 q = approximate_closest(p, t.a, t.b, t.c);
  const Vec3 w = p - q;
  const double ww = dot(w, w);
  // hi: |p - q| with |w| rounded per coordinate (relative eps each, 3 eps for the sum of
  // squares), times (1 + 2^-20) for the cross term, plus the slack.
  // Squares that underflow lose up to 2^-1075 each: 8 subnormal units cover them.
  hi = ww * (1 + 0x1p-19) + slack + 8 * std::numeric_limits<double>::denorm_min();
  if (!std::isfinite(hi)) hi = kInf;
  const double smin = std::min(
      {separation_lower(p, t.a, w), separation_lower(p, t.b, w), separation_lower(p, t.c, w)});
  lo = 0.0;
  if (smin > 0 && ww >= 0x1p-900 && std::isfinite(ww)) {
    const double r = smin / ww;
    if (r >= 0x1p-1000 && std::isfinite(r)) {
      // smin^2 / ww with three roundings (quotient, product, the factor): (1 - 8 eps).
      lo = smin * r * (1 - 8 * kEps);
    }
  }
}

double box_lower_bound(Vec3 p, const Box3& box) {
  const double dx = std::max({box.min.x - p.x, p.x - box.max.x, 0.0});
  const double dy = std::max({box.min.y - p.y, p.y - box.max.y, 0.0});
  const double dz = std::max({box.min.z - p.z, p.z - box.max.z, 0.0});
  // Each difference rounded (eps), squares and sums (3 eps): 8 eps covers them and the factor.
  // A square that underflows only lowers the bound; an overflow means > DBL_MAX exactly.
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

namespace {

float round_down(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float round_up(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// box_lower_bound for a float box of a pair node, read in double (exact conversions).
inline double float_box_lower_bound(Vec3 p, const float lo[3], const float hi[3]) {
  const double dx =
      std::max(std::max(static_cast<double>(lo[0]) - p.x, p.x - static_cast<double>(hi[0])), 0.0);
  const double dy =
      std::max(std::max(static_cast<double>(lo[1]) - p.y, p.y - static_cast<double>(hi[1])), 0.0);
  const double dz =
      std::max(std::max(static_cast<double>(lo[2]) - p.z, p.z - static_cast<double>(hi[2])), 0.0);
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

}  // namespace

TriangleSearch::TriangleSearch(std::span<const Triangle3> triangles,
                               const bvh::BuildOptions& options)
    : triangles_(triangles.begin(), triangles.end()) {
  std::vector<Box3> boxes;
  boxes.reserve(triangles_.size());
  double max_abs = 0.0;
  for (const Triangle3& t : triangles_) {
    Box3 b;
    b.expand(t.a);
    b.expand(t.b);
    b.expand(t.c);
    boxes.push_back(b);
    max_abs = std::max({max_abs, std::fabs(b.min.x), std::fabs(b.min.y), std::fabs(b.min.z),
                        std::fabs(b.max.x), std::fabs(b.max.y), std::fabs(b.max.z)});
  }
  bvh_ = bvh::Bvh(boxes, options);
  tris_.reserve(triangles_.size());
  position_.assign(triangles_.size(), 0);
  for (const std::int32_t i : bvh_.items()) {
    const Triangle3& t = triangles_[static_cast<std::size_t>(i)];
    position_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(tris_.size());
    tris_.push_back({t.a, t.b, t.c, i});
  }
  slack_ = triangle_slack(max_abs);
  build_pair_nodes();
}

void TriangleSearch::build_pair_nodes() {
  const std::span<const bvh::Node> nodes = bvh_.nodes();
  if (nodes.empty() || nodes[0].is_leaf()) return;
  std::vector<std::int32_t> pair_of(nodes.size(), -1);
  std::int32_t k = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].is_leaf()) pair_of[i] = k++;
  pairs_.resize(static_cast<std::size_t>(k));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].is_leaf()) continue;
    PairNode& pn = pairs_[static_cast<std::size_t>(pair_of[i])];
    const std::size_t children[2] = {i + 1, static_cast<std::size_t>(nodes[i].first)};
    for (int c = 0; c < 2; ++c) {
      const bvh::Node& child = nodes[children[c]];
      pn.lo[c][0] = round_down(child.box.min.x);
      pn.lo[c][1] = round_down(child.box.min.y);
      pn.lo[c][2] = round_down(child.box.min.z);
      pn.hi[c][0] = round_up(child.box.max.x);
      pn.hi[c][1] = round_up(child.box.max.y);
      pn.hi[c][2] = round_up(child.box.max.z);
      if (child.is_leaf()) {
        pn.child[c] = child.first;
        pn.count[c] = child.count;
      } else {
        pn.child[c] = pair_of[children[c]];
        pn.count[c] = 0;
      }
    }
  }
}

void TriangleSearch::bound_leaf(Vec3 p, std::int32_t first, std::int32_t count, std::int32_t skip,
                                double& best, std::vector<Contender>& out,
                                std::size_t& bounded) const {
  for (std::int32_t k = first; k < first + count; ++k) {
    if (k == skip) continue;
    ++bounded;
    const Tri& t = tris_[static_cast<std::size_t>(k)];
    double lo = 0.0, hi = 0.0;
    triangle_bounds(p, {t.a, t.b, t.c}, slack_, lo, hi);
    if (lo > best) continue;
    out.push_back({t.index, lo, hi});
    if (hi < best) best = hi;
  }
}

void TriangleSearch::contenders(Vec3 p, std::vector<Contender>& out, SearchStats* stats,
                                std::int32_t hint) const {
  out.clear();
  if (tris_.empty()) return;
  double best = kInf;
  std::int32_t skip = -1;
  std::size_t visited_tris = 0;
  if (hint >= 0 && static_cast<std::size_t>(hint) < position_.size()) {
    skip = position_[static_cast<std::size_t>(hint)];
    bound_leaf(p, skip, 1, -1, best, out, visited_tris);
  }
  std::size_t visited_nodes = 0;
  if (pairs_.empty()) {  // the root is a leaf
    const bvh::Node& root = bvh_.nodes()[0];
    bound_leaf(p, root.first, root.count, skip, best, out, visited_tris);
  } else {
    struct Entry {
      std::int32_t node;
      double lb;
    };
    Entry local[128];
    std::vector<Entry> heap;
    Entry* stack = local;
    if (bvh_.depth() > 120) {
      heap.resize(static_cast<std::size_t>(bvh_.depth()) + 8);
      stack = heap.data();
    }
    int top = 0;
    stack[top++] = {0, box_lower_bound(p, bvh_.nodes()[0].box)};
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.lb > best) continue;
      const PairNode& node = pairs_[static_cast<std::size_t>(e.node)];
      ++visited_nodes;
      const double l0 = float_box_lower_bound(p, node.lo[0], node.hi[0]);
      const double l1 = float_box_lower_bound(p, node.lo[1], node.hi[1]);
      const int near = l1 < l0 ? 1 : 0;
      const int far = 1 - near;
      const double lnear = near == 0 ? l0 : l1;
      const double lfar = near == 0 ? l1 : l0;
      // The far child waits on the stack (or is bounded now if it is a leaf, after the near one).
      if (lfar <= best && node.count[far] == 0) stack[top++] = {node.child[far], lfar};
      if (lnear <= best) {
        if (node.count[near] > 0) {
          bound_leaf(p, node.child[near], node.count[near], skip, best, out, visited_tris);
        } else {
          stack[top++] = {node.child[near], lnear};
        }
      }
      if (node.count[far] > 0 && lfar <= best) {
        bound_leaf(p, node.child[far], node.count[far], skip, best, out, visited_tris);
      }
    }
  }
  std::erase_if(out, [best](const Contender& c) { return c.lo > best; });
  if (stats) {
    stats->nodes += visited_nodes;
    stats->triangles += visited_tris;
  }
}

int TriangleSearch::within(Vec3 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const {
  out.clear();
  if (tris_.empty()) return -1;
  const std::span<const bvh::Node> nodes = bvh_.nodes();
  std::vector<std::int32_t> stack;
  stack.reserve(static_cast<std::size_t>(bvh_.depth()) + 8);
  stack.push_back(0);
  while (!stack.empty()) {
    const std::int32_t index = stack.back();
    stack.pop_back();
    const bvh::Node& node = nodes[static_cast<std::size_t>(index)];
    if (box_lower_bound(p, node.box) > d2_hi) continue;
    if (!node.is_leaf()) {
      stack.push_back(node.first);
      stack.push_back(index + 1);
      continue;
    }
    for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
      const Tri& t = tris_[static_cast<std::size_t>(k)];
      double lo = 0.0, hi = 0.0;
      triangle_bounds(p, {t.a, t.b, t.c}, slack_, lo, hi);
      if (hi <= d2_lo) {
        out.clear();
        return 1;
      }
      if (lo <= d2_hi) out.push_back({t.index, lo, hi});
    }
  }
  return out.empty() ? -1 : 0;
}

}  // namespace contain::distance::detail
