#pragma once
/// \file
/// Stable LSD radix sort of (key, item) pairs by key: the one implementation shared by the linear
/// BVH build (Morton codes) and MeshIndex (triangles by cell).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace contain {

/// Sorts `keys` ascending, moving `items` (the same size) along; equal keys keep their order, so
/// the result is the order of a sort of the pairs (key, position). Only the low `key_bits` bits of
/// the keys are read (the others must be zero). 11 bits a pass; a pass whose digit is the same for
/// every key is skipped. O((n + 2^11) key_bits / 11).
template <class Item>
void stable_radix_sort(std::vector<std::uint64_t>& keys, std::vector<Item>& items,
                       unsigned key_bits) {
  constexpr unsigned digit_bits = 11;
  constexpr std::size_t buckets = std::size_t{1} << digit_bits;
  const std::size_t n = keys.size();
  std::vector<std::uint64_t> keys_out(n);
  std::vector<Item> items_out(n);
  std::vector<std::size_t> start(buckets + 1);
  for (unsigned shift = 0; shift < key_bits; shift += digit_bits) {
    std::fill(start.begin(), start.end(), 0);
    for (const std::uint64_t k : keys)
      ++start[((k >> shift) & (buckets - 1)) + 1];
    if (std::find(start.begin(), start.end(), n) != start.end()) continue;
    for (std::size_t b = 1; b <= buckets; ++b)
      start[b] += start[b - 1];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t at = start[(keys[i] >> shift) & (buckets - 1)]++;
      keys_out[at] = keys[i];
      items_out[at] = items[i];
    }
    keys.swap(keys_out);
    items.swap(items_out);
  }
}

}  // namespace contain
