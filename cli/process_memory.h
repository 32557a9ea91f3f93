#pragma once
// How the contain process asks for memory: freed blocks kept for reuse and the heap in
// transparent huge pages (process_memory.cpp says why). Called once, first thing in main.

namespace contain::cli {

/// On Linux with glibc: large blocks from the heap rather than one mapping each, freed memory
/// kept in the process instead of returned to the system, and a first stretch of heap reserved
/// and marked for transparent huge pages (a hint: ordinary pages where it is not granted).
/// Elsewhere, and under sanitizers whose allocators replace malloc, nothing changes.
void tune_process_memory();

}  // namespace contain::cli
