#pragma once
/// \file
/// Large arrays in transparent huge pages where the system grants them on request (Linux with
/// transparent_hugepage "madvise" or "always"): a 2 MB page is one page fault where 4 kB pages
/// are 512, and for arrays of megabytes written once (a MeshIndex's cells and triangle lists)
/// those faults and the kernel's bookkeeping behind them are a large part of the build.

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

#include "contain/core/default_init.h"

namespace contain {

namespace detail {

inline constexpr std::size_t huge_page_bytes = std::size_t{1} << 21;

/// A block of `bytes` (a positive multiple of `huge_page_bytes`) on a `huge_page_bytes` boundary,
/// advised for huge pages where the system has the call (src/core/huge_pages.cpp: the platform
/// calls stay out of the public headers). Throws std::bad_alloc when the system has no room.
[[nodiscard]] void* allocate_huge_page_block(std::size_t bytes);
/// Gives back a block of allocate_huge_page_block.
void free_huge_page_block(void* block) noexcept;

}  // namespace detail

/// An allocator that places blocks of at least `huge_page_threshold` bytes on 2 MB boundaries,
/// rounded up to whole 2 MB pages, and asks the system to back them with huge pages when first
/// touched (a hint: where it is not granted the block is ordinary memory). Smaller blocks come
/// from `std::allocator`. Stateless: all instances compare equal.
///
/// Elements made without arguments are default-initialized (DefaultInitConstruct).
template <class T>
struct HugePageAllocator : DefaultInitConstruct {
  using value_type = T;
  static constexpr std::size_t huge_page = detail::huge_page_bytes;
  /// Below this (128 kB), the slack of a 2 MB rounding is not worth it. Measured on the 2-core
  /// VM of docs/benchmarks.md: the first touch of a 4 kB page costs about 12 us there (49 ms for
  /// 16 MB), of a 2 MB huge page about 160 us (1.3 ms for 16 MB), so a block of 32 small pages
  /// already costs more than one huge page; where faults are cheap it is about even.
  static constexpr std::size_t huge_page_threshold = std::size_t{1} << 17;

  HugePageAllocator() = default;
  template <class U>
  explicit(false) HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > max_size()) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_page_threshold || alignof(T) > huge_page) {
      return std::allocator<T>{}.allocate(n);
    }
    const std::size_t rounded = (bytes + huge_page - 1) & ~(huge_page - 1);
    return static_cast<T*>(detail::allocate_huge_page_block(rounded));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < huge_page_threshold || alignof(T) > huge_page) {
      std::allocator<T>{}.deallocate(p, n);
      return;
    }
    detail::free_huge_page_block(p);
  }
  [[nodiscard]] static constexpr std::size_t max_size() noexcept {
    return (std::size_t{0} - huge_page) / sizeof(T);
  }

  template <class U>
  friend bool operator==(const HugePageAllocator& /*a*/, const HugePageAllocator<U>& /*b*/) {
    return true;
  }
};

/// A vector whose large buffers sit in huge pages (HugePageAllocator).
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace contain
