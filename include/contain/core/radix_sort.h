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
/// the keys are read (the others must be zero). 11 bits a pass, all passes counted in one read of
/// the keys; a pass whose digit is the same for every key is skipped. O((n + 2^11) key_bits / 11).
template <class Item>
void stable_radix_sort(std::vector<std::uint64_t>& keys, std::vector<Item>& items,
                       unsigned key_bits) {
  constexpr unsigned digit_bits = 11;
  constexpr std::size_t buckets = std::size_t{1} << digit_bits;
  constexpr unsigned max_passes = (64 + digit_bits - 1) / digit_bits;
  const std::size_t n = keys.size();
  const unsigned passes = std::min((key_bits + digit_bits - 1) / digit_bits, max_passes);
  // Every pass's counts from one read of the keys (a pass's scatter does not change the multiset
  // of its keys, so the counts of later digits stay valid).
  std::vector<std::size_t> counts(static_cast<std::size_t>(passes) * (buckets + 1));
  for (const std::uint64_t k : keys) {
    for (unsigned p = 0; p < passes; ++p)
      ++counts[p * (buckets + 1) + ((k >> (p * digit_bits)) & (buckets - 1)) + 1];
  }
  std::vector<std::uint64_t> keys_out;
  std::vector<Item> items_out;
  for (unsigned p = 0; p < passes; ++p) {
    const unsigned shift = p * digit_bits;
    const auto start = counts.begin() + static_cast<std::ptrdiff_t>(p * (buckets + 1));
    if (std::find(start, start + static_cast<std::ptrdiff_t>(buckets + 1), n) !=
        start + static_cast<std::ptrdiff_t>(buckets + 1)) {
      continue;
    }
    if (keys_out.size() != n) {
      keys_out.resize(n);
      items_out.resize(n);
    }
    for (std::size_t b = 1; b <= buckets; ++b)
      start[static_cast<std::ptrdiff_t>(b)] += start[static_cast<std::ptrdiff_t>(b - 1)];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t at =
          start[static_cast<std::ptrdiff_t>((keys[i] >> shift) & (buckets - 1))]++;
      keys_out[at] = keys[i];
      items_out[at] = items[i];
    }
    keys.swap(keys_out);
    items.swap(items_out);
  }
}

}  // namespace contain
