#pragma once
/// \file
/// The construction half of an allocator whose containers leave new trivial elements unwritten:
/// shared by HugePageAllocator and the mesh boolean's scratch allocator.

#include <new>
#include <type_traits>
#include <utility>

namespace contain {

/// A base for allocators (through std::allocator_traits, which calls these where present):
/// elements made without arguments are default-initialized, not value-initialized, so
/// `resize(n)` of a vector of a trivial type leaves the new elements' values indeterminate, for
/// a caller that writes every one of them next (a large array is not zeroed only to be
/// overwritten). Elements made with arguments are made from them as usual. Stateless.
struct DefaultInitConstruct {
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace contain
