#pragma once
/// \file
/// Disjoint sets over 0..n-1 (union-find), the one implementation shared by mesh validation
/// (corners of a vertex's fans, components) and the polygon boolean (components, face regions).

#include <algorithm>
#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace contain {

/// Disjoint sets over the indices 0..n-1 of type `Index` (std::uint32_t keeps large sets small),
/// the parents in a vector of `Allocator` (a caller's scratch memory, say).
/// The representative of a set is its smallest element, so answers do not depend on the order
/// of joins. find() halves paths; without union by rank a find is O(log n) amortised, which is
/// enough for the sets here (each join and find is near O(1) in practice).
template <class Index, class Allocator = std::allocator<Index>>
class UnionFind {
 public:
  /// n singletons.
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }

  /// n singletons again, reusing the storage (one set per vertex of a mesh, say, without an
  /// allocation each).
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }

  /// The representative (smallest element) of x's set. Precondition: x < n.
  [[nodiscard]] Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  /// Merges the sets of a and b. Precondition: a, b < n.
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index, Allocator> parent_;
};

}  // namespace contain
