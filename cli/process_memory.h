#pragma once
// How a solid boolean's process asks for memory: freed blocks kept for reuse (process_memory.cpp
// says why). Called by `contain clip` before it reads solids; not by the verbs that stream
// points, whose answers grow by doubling: there a kept old block would stay in the process beside
// the new one (10^8 points from stdin: 322 MB peak instead of 234 MB).

namespace contain::cli {

/// On Linux with glibc: large blocks from the heap rather than one mapping each, and freed memory
/// kept in the process instead of returned to the system. Elsewhere, and under sanitizers whose
/// allocators replace malloc, nothing changes.
void keep_freed_memory_for_reuse();

}  // namespace contain::cli
