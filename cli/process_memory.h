#pragma once
// How the contain process asks for memory: freed blocks kept for reuse (process_memory.cpp says
// why). Called once, first thing in main.

namespace contain::cli {

/// On Linux with glibc: large blocks from the heap rather than one mapping each, and freed memory
/// kept in the process instead of returned to the system. Elsewhere, and under sanitizers whose
/// allocators replace malloc, nothing changes.
void tune_process_memory();

}  // namespace contain::cli
