// Memory for a short process that builds and drops large arrays stage after stage (the mesh
// boolean: a soup, a point store, the refinement, labels, the written mesh and its check).
//
// glibc serves each block of more than 128 kB to 32 MB by a mapping of its own and returns it on
// free, so the next stage's arrays are fresh pages again: every 4 kB page faulted and zeroed by
// the kernel, 46,000 faults and about a fifth of a boolean of two 131k-triangle spheres. Here
// every block comes from the heap (M_MMAP_MAX 0), freed memory stays in it (no trimming), and
// the heap's first stretch (a quarter of the machine's memory, at most 1 GB of address space:
// only the pages touched are memory) is reserved at once and marked MADV_HUGEPAGE, so that a
// fault brings 2 MB where it brought 4 kB. What the glibc tunables glibc.malloc.hugetlb=1 and
// trim_threshold do, without asking the user to set them.

#include "process_memory.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace contain::cli {

void tune_process_memory() {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge_page = std::uintptr_t{1} << 21U;
  constexpr std::size_t most = std::size_t{1} << 30U;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return;
  const std::size_t quarter = static_cast<std::size_t>(pages) / 4 * static_cast<std::size_t>(page);
  const std::size_t reserve = quarter < most ? quarter : most;
  if (reserve < 4 * huge_page) return;
  (void)mallopt(M_MMAP_MAX, 0);
  (void)mallopt(M_TRIM_THRESHOLD, -1);  // never give the heap's top back
  // One growth of the heap by `reserve` (a block larger than its small first top forces it),
  // then the default padding again.
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  (void)mallopt(M_TOP_PAD, static_cast<int>(reserve));
  void* block = std::malloc(2 * huge_page);
  (void)mallopt(M_TOP_PAD, 128 * 1024);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(block);
  const std::uintptr_t first = (before + huge_page - 1) & ~(huge_page - 1);
  const std::uintptr_t last = after & ~(huge_page - 1);
  if (block == nullptr || after <= before || last <= first) return;  // another allocator
  (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

}  // namespace contain::cli
