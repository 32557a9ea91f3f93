#include "distance/search_tree.h"

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
      to_float(child.box, pn.lo[c], pn.hi[c]);
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

}  // namespace contain::distance::detail
