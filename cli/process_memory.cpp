// Memory for a short process that builds and drops large arrays stage after stage (the mesh
// boolean: a soup, a point store, the refinement, labels, the written mesh and its check).
//
// glibc serves each block of more than 128 kB to 32 MB by a mapping of its own and returns it on
// free, so the next stage's arrays are fresh pages again: every 4 kB page faulted and zeroed by
// the kernel, 46,600 faults and about a tenth of a boolean of two 131k-triangle spheres. Here
// every block comes from the heap (M_MMAP_MAX 0) and freed memory stays in it (no trimming), so
// later stages reuse the pages of earlier ones: 35,000 faults. Freed blocks are not given back,
// so only `contain clip` on solids asks for this: a verb whose arrays grow by doubling (the
// answers of streamed points) would keep each old block beside the new one (process_memory.h).
//
// Tried and dropped: the heap marked for transparent huge pages (MADV_HUGEPAGE on a first 1 GB):
// 1,000 faults and 20% faster at first, but on the benchmark machine (a KVM guest) a fresh huge
// page's zeroing then took the host's faults, up to 1.5 s of system time at the 524k union.

#include "process_memory.h"

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#endif

namespace contain::cli {

void keep_freed_memory_for_reuse() {
#if defined(__linux__) && defined(__GLIBC__)
  (void)mallopt(M_MMAP_MAX, 0);
  (void)mallopt(M_TRIM_THRESHOLD, -1);  // never give the heap's top back
#endif
}

}  // namespace contain::cli
