#include "distance/search_tree.h"

#include <array>

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
void to_float(const Box3& b, float lo[3], float hi[3]) {
  lo[0] = round_down(b.min.x);
  lo[1] = round_down(b.min.y);
  lo[2] = round_down(b.min.z);
  hi[0] = round_up(b.max.x);
  hi[1] = round_up(b.max.y);
  hi[2] = round_up(b.max.z);
}

}  // namespace

SearchTree::SearchTree(std::span<const Box3> boxes, const bvh::BuildOptions& options) {
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
    const float inf = std::numeric_limits<float>::infinity();
    for (std::size_t c = 0; c < 4; ++c) {
      float lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
      if (c < size) {
        const bvh::Node& child = nodes[group[c]];
        to_float(child.box, lo, hi);
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
        q.child[c] = 0;
        q.count[c] = -1;
      }
      for (int a = 0; a < 3; ++a) {
        q.lo[a][c] = lo[a];
        q.hi[a][c] = hi[a];
      }
    }
    quads_[at.quad] = q;
  }
}

}  // namespace contain::distance::detail
