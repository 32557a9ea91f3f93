#pragma once
/// \file
/// Stable LSD radix sort of (key, item) pairs by key: the one implementation shared by the linear
/// BVH build (Morton codes) and MeshIndex (triangles by cell).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace contain {

/// Sorts `keys` (unsigned integers) ascending, moving `items` (the same size) along; equal keys
/// keep their order, so the result is the order of a sort of the pairs (key, position). Only the
/// low `key_bits` bits of the keys are read (the others must be zero). 11 bits a pass, all passes
/// counted in one read of the keys; a pass whose digit is the same for every key is skipped.
/// O((n + 2^11) key_bits / 11). The two scratch arrays take the vectors' allocators: one that
/// default-initializes (HugePageAllocator) leaves them unzeroed, each element written by the pass
/// before it is read.
template <class Key, class KeyAllocator, class Item, class ItemAllocator>
void stable_radix_sort(std::vector<Key, KeyAllocator>& keys,
                       std::vector<Item, ItemAllocator>& items, unsigned key_bits) {
  static_assert(std::is_unsigned_v<Key>, "radix keys are unsigned integers");
  constexpr unsigned digit_bits = 11;
  constexpr std::size_t buckets = std::size_t{1} << digit_bits;
  const std::size_t n = keys.size();
  const unsigned bits = std::min<unsigned>(key_bits, 8 * sizeof(Key));
  const unsigned passes = (bits + digit_bits - 1) / digit_bits;
  // Every pass's counts from one read of the keys (a pass's scatter does not change the multiset
  // of its keys, so the counts of later digits stay valid).
  std::vector<std::size_t> counts(static_cast<std::size_t>(passes) * (buckets + 1));
  for (const Key k : keys) {
    for (unsigned p = 0; p < passes; ++p)
      ++counts[p * (buckets + 1) + ((k >> (p * digit_bits)) & (buckets - 1)) + 1];
  }
  std::vector<Key, KeyAllocator> keys_out;
  std::vector<Item, ItemAllocator> items_out;
  for (unsigned p = 0; p < passes; ++p) {
    const unsigned shift = p * digit_bits;
    std::size_t* const start = counts.data() + p * (buckets + 1);
    if (std::find(start, start + buckets + 1, n) != start + buckets + 1) continue;
    if (keys_out.size() != n) {
      keys_out.resize(n);
      items_out.resize(n);
    }
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
