#include "distance/search_tree.h"

#include <array>
#include <utility>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"
#include "distance/oriented_box.h"

namespace contain::distance::detail {

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

// The oriented box of one lane around the corners `points`: the principal axes rounded to
// floats (the coordinate axes where they fail or `principal` is false), and along each axis u the
// extent of u . (v - o) over the corners v, widened by a bound on its rounding and rounded outward:
// d = fl(v - o) is within eps |d_i| per coordinate, the dot product within gamma_3 of its
// permanent, and |u|_1 <= 1.75, so 8 eps (permanent + max |d_i|) and 2^-1000 (products that
// underflow) cover both, the subtraction or addition of the bound included. k from Gershgorin:
// lambda_max(U U^T) is at most the largest row sum of |u_a . u_b|, each dot product of floats
// within 3 eps of its value (at most 1.01 here).
void fill_lane(std::span<const Vec3> points, Vec3 o, bool principal, int lane, OrientedLanes& out) {
  Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (principal) principal_axes(points, e);
  Vec3 u[3];
  for (int a = 0; a < 3; ++a) {
    u[a] = {static_cast<float>(e[a].x), static_cast<float>(e[a].y), static_cast<float>(e[a].z)};
    if (!((std::fabs(u[a].x) + std::fabs(u[a].y)) + std::fabs(u[a].z) <= 1.75)) {
      u[0] = {1, 0, 0};
      u[1] = {0, 1, 0};
      u[2] = {0, 0, 1};
      break;
    }
  }
  for (int a = 0; a < 3; ++a) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Vec3& v : points) {
      const Vec3 d = v - o;
      const double t = dot(u[a], d);
      const double perm =
          (std::fabs(u[a].x * d.x) + std::fabs(u[a].y * d.y)) + std::fabs(u[a].z * d.z);
      const double big = max_abs(d);
      const double err = 8 * kEps * (perm + big) + 0x1p-1000;
      lo = std::min(lo, t - err);
      hi = std::max(hi, t + err);
    }
    // NaN or overflow: a lane that holds everything.
    out.lo[a][lane] = std::isfinite(lo) ? round_down(lo) : -std::numeric_limits<float>::infinity();
    out.hi[a][lane] = std::isfinite(hi) ? round_up(hi) : std::numeric_limits<float>::infinity();
    out.axis[a][0][lane] = static_cast<float>(u[a].x);
    out.axis[a][1][lane] = static_cast<float>(u[a].y);
    out.axis[a][2][lane] = static_cast<float>(u[a].z);
  }
  double row_max = 0;
  for (int a = 0; a < 3; ++a) {
    double row = 0;
    for (int b = 0; b < 3; ++b)
      row += std::fabs(dot(u[a], u[b])) + 8 * kEps;
    row_max = std::max(row_max, row);
  }
  out.k[lane] = round_down(1.0 / (row_max * (1 + 8 * kEps)) * (1 - 8 * kEps));
}

// Children over more items than this get the coordinate axes around their axis-aligned box: near
// the root an oriented box prunes little more, and gathering every corner at every level would
// cost time and, for a mesh of millions of triangles, a copy of a quarter of its corners.
constexpr std::size_t kMaxOriented = 512;

// An empty lane: its bound is as large as lanes' bounds get (the search skips it by its count).
void fill_empty_lane(int lane, OrientedLanes& out) {
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < 3; ++i)
      out.axis[a][i][lane] = a == i ? 1.0f : 0.0f;
    out.lo[a][lane] = std::numeric_limits<float>::infinity();
    out.hi[a][lane] = -std::numeric_limits<float>::infinity();
  }
  out.k[lane] = 0.25f;
}

void to_float(const Box3& b, float lo[3], float hi[3]) {
  lo[0] = round_down(b.min.x);
  lo[1] = round_down(b.min.y);
  lo[2] = round_down(b.min.z);
  hi[0] = round_up(b.max.x);
  hi[1] = round_up(b.max.y);
  hi[2] = round_up(b.max.z);
}

}  // namespace

SearchTree::SearchTree(std::span<const Vec3> corners, int per_item,
                       const bvh::BuildOptions& options) {
  const auto per = static_cast<std::size_t>(per_item);
  std::vector<Box3> boxes(per == 0 ? 0 : corners.size() / per);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = 0; j < per; ++j)
      boxes[i].expand(corners[i * per + j]);
  const bvh::Bvh tree(boxes, options);
  items_.assign(tree.items().begin(), tree.items().end());
  position_.assign(items_.size(), 0);
  for (std::size_t k = 0; k < items_.size(); ++k)
    position_[static_cast<std::size_t>(items_[k])] = static_cast<std::int32_t>(k);
  depth_ = tree.depth();
  const std::span<const bvh::Node> nodes = tree.nodes();
  if (nodes.empty()) return;
  to_float(nodes[0].box, root_lo_, root_hi_);
  if (nodes[0].is_leaf()) {
    root_count_ = nodes[0].count;
    return;
  }
  origin_ = 0.5 * (nodes[0].box.min + nodes[0].box.max);
  if (!is_finite(origin_)) origin_ = {};
  const std::vector<std::pair<std::int32_t, std::int32_t>> range = item_ranges(nodes);
  std::vector<Vec3> points;
  // Each quad node gathers up to four nodes below a binary inner node: its two children, then
  // repeatedly the inner one of largest box area split into its two, while there is room.
  auto children_of = [&](std::size_t i) {
    return std::array<std::size_t, 2>{i + 1, static_cast<std::size_t>(nodes[i].first)};
  };
  auto area = [&](std::size_t i) {
    const Vec3 d = nodes[i].box.max - nodes[i].box.min;
    return d.x * d.y + d.y * d.z + d.z * d.x;
  };
  struct Pending {
    std::size_t binary;  // a binary inner node
    std::size_t quad;    // its quad node
  };
  std::vector<Pending> pending{{0, 0}};
  quads_.emplace_back();
  while (!pending.empty()) {
    const Pending at = pending.back();
    pending.pop_back();
    std::array<std::size_t, 4> group{};
    const auto first = children_of(at.binary);
    group[0] = first[0];
    group[1] = first[1];
    std::size_t size = 2;
    while (size < 4) {
      std::size_t widest = size;
      for (std::size_t k = 0; k < size; ++k) {
        if (nodes[group[k]].is_leaf()) continue;
        if (widest == size || area(group[k]) > area(group[widest])) widest = k;
      }
      if (widest == size) break;
      const auto split = children_of(group[widest]);
      group[widest] = split[0];
      group[size++] = split[1];
    }
    QuadNode q{};
    for (std::size_t c = 0; c < 4; ++c) {
      if (c < size) {
        const bvh::Node& child = nodes[group[c]];
        points.clear();
        const auto lo = static_cast<std::size_t>(range[group[c]].first);
        const auto hi = static_cast<std::size_t>(range[group[c]].second);
        if (hi - lo > kMaxOriented) {
          // The corners of the child's axis-aligned box: their hull holds every item.
          for (int k = 0; k < 8; ++k)
            points.push_back({(k & 1) != 0 ? child.box.max.x : child.box.min.x,
                              (k & 2) != 0 ? child.box.max.y : child.box.min.y,
                              (k & 4) != 0 ? child.box.max.z : child.box.min.z});
        } else {
          for (std::size_t k = lo; k < hi; ++k) {
            const auto item = static_cast<std::size_t>(items_[k]);
            points.insert(points.end(), corners.begin() + static_cast<std::ptrdiff_t>(item * per),
                          corners.begin() + static_cast<std::ptrdiff_t>((item + 1) * per));
          }
        }
        fill_lane(points, origin_, hi - lo <= kMaxOriented, static_cast<int>(c), q.box);
        if (child.is_leaf()) {
          q.child[c] = child.first;
          q.count[c] = child.count;
        } else {
          q.child[c] = static_cast<std::int32_t>(quads_.size());
          q.count[c] = 0;
          pending.push_back({group[c], quads_.size()});
          quads_.emplace_back();
        }
      } else {
        fill_empty_lane(static_cast<int>(c), q.box);
        q.child[c] = 0;
        q.count[c] = -1;
      }
    }
    quads_[at.quad] = q;
  }
}

std::vector<SearchTree::LaneBound> SearchTree::lane_bounds(Vec3 p) const {
  std::vector<LaneBound> out;
  if (quads_.empty()) return out;
  const LanePoint q = lane_point(p, origin_);
  // The item range of a node's lanes, its own lanes listed first.
  auto visit = [&](auto&& self, std::int32_t index) -> std::pair<std::int32_t, std::int32_t> {
    const QuadNode& node = quads_[static_cast<std::size_t>(index)];
    double lb[4];
    oriented_lower_bound4(q, node.box, lb);
    std::int32_t first = std::numeric_limits<std::int32_t>::max(), end = 0;
    for (int c = 0; c < 4; ++c) {
      if (node.count[c] < 0) continue;
      std::pair<std::int32_t, std::int32_t> r{node.child[c], node.child[c] + node.count[c]};
      const std::size_t at = out.size();
      out.push_back({lb[c], 0, 0});
      if (node.count[c] == 0) r = self(self, node.child[c]);
      out[at].first = r.first;
      out[at].end = r.second;
      first = std::min(first, r.first);
      end = std::max(end, r.second);
    }
    return {first, end};
  };
  visit(visit, 0);
  return out;
}

}  // namespace contain::distance::detail
