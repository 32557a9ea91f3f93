#include "contain/core/huge_pages.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace contain::detail {

void* allocate_huge_page_block(std::size_t bytes) {
  void* block = std::aligned_alloc(huge_page_bytes, bytes);
  if (block == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // A hint: where huge pages are not granted the block is ordinary memory.
  (void)::madvise(block, bytes, MADV_HUGEPAGE);
#endif
  return block;
}

void free_huge_page_block(void* block) noexcept {
  std::free(block);
}

}  // namespace contain::detail
