#pragma once
// Scratch memory of one mesh boolean: the large arrays of its stages carved out of a few chunks
// that the call owns, so that the pages a stage wrote and freed are the next stages' pages.
// Private to clip.
//
// The stages build and drop arrays of megabytes one after another (a soup, a point store, the
// pairs' work, the refinement, labels, the merged faces, the sheets and the written mesh's
// check). The C library serves each such block by a mapping of its own and unmaps it on free
// (glibc: from 128 kB, the threshold rising with the blocks freed), so the next stage faulted in
// fresh pages, each zeroed by the kernel (about 11 us a 4 kB page on the benchmark VM at a busy
// hour). The CLI changes the process's malloc for this (cli/process_memory.h); a library cannot,
// and its cost must not depend on its caller's settings. So each call owns a ScratchPool and
// installs it with a ScratchScope; the engine's large arrays (ScratchVector) are placed in its
// chunks, lowest address first, freed ranges joined with their free neighbours: a chunk's pages
// are written once and then reused, and the pages a call touches are about its largest live set.
// A pool gives its chunks back when it is destroyed (a chunk that still holds a block, which
// then outlives its call, when that block is freed).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "contain/core/default_init.h"

namespace contain::clip::solid {

namespace detail {
struct ScratchChunk;
}  // namespace detail

/// Chunks of memory, each carved into blocks by address-ordered first fit with coalescing. Not
/// thread-safe: one per call, on the thread that installed it (the engine runs on one thread).
class ScratchPool {
 public:
  /// Blocks of at least this many bytes come from the pool: smaller ones the heap reuses itself
  /// (glibc maps blocks of their own from 128 kB on).
  static constexpr std::size_t min_bytes = std::size_t{1} << 17;
  /// Blocks are whole pages (their header included): a freed block's pages are then all
  /// reusable, and no two blocks share a page.
  static constexpr std::size_t granule = std::size_t{1} << 12;
  /// The least size of a chunk (later ones are as large as all before). Its pages are touched
  /// only where blocks are written, but a chunk's end that no block fits is left unused, and
  /// where the process keeps freed memory (the CLI's malloc settings) the allocations after the
  /// call land in the chunks given back. Page faults of a union of two 131k-triangle spheres,
  /// inside the call (kernel bench) and the CLI's whole process: 17,127 and 16,412 with 16 MB
  /// chunks, 16,936 and 16,944 with 32 MB, 17,147 and 17,142 with 64 MB.
  static constexpr std::size_t min_chunk = std::size_t{1} << 25;

  ScratchPool() = default;
  ScratchPool(const ScratchPool&) = delete;
  ScratchPool& operator=(const ScratchPool&) = delete;
  ~ScratchPool();

  /// A range of `bytes` (a positive multiple of `granule`) in a chunk: the lowest free one
  /// large enough in the oldest chunk that has one, else at the start of a new chunk. Throws
  /// std::bad_alloc when the system has no room.
  [[nodiscard]] std::pair<detail::ScratchChunk*, std::size_t> acquire(std::size_t bytes);
  /// Frees the range of `bytes` at `offset` of `chunk` (one of this pool's, from acquire).
  void release(detail::ScratchChunk* chunk, std::size_t offset, std::size_t bytes) noexcept;

  /// Chunks made, and their bytes.
  [[nodiscard]] std::size_t chunks() const { return chunks_.size(); }
  [[nodiscard]] std::size_t reserved_bytes() const;
  /// Bytes in blocks now.
  [[nodiscard]] std::size_t used_bytes() const { return used_; }
  /// The bytes of all chunks below the highest end of any block they ever held: a bound on the
  /// pages the pool's blocks touched.
  [[nodiscard]] std::size_t high_water_bytes() const;

 private:
  struct Free {
    std::size_t chunk;  // index in chunks_: older chunks first
    std::size_t offset, bytes;
  };
  std::vector<detail::ScratchChunk*> chunks_;
  std::vector<Free> free_;  // by (chunk, offset); neighbours never adjacent (joined)
  std::size_t blocks_ = 0;  // held now
  std::size_t used_ = 0;
};

/// Installs a pool for this thread while alive (the one the thread had before is restored
/// after: scopes nest, a boolean inside a boolean uses its own). Blocks are given back to the
/// pool they came from, whichever is installed when they are freed.
class ScratchScope {
 public:
  explicit ScratchScope(ScratchPool& pool);
  /// Installs `pool`, or no pool for nullptr (blocks from operator new, so from the process's
  /// heap and its malloc settings).
  explicit ScratchScope(ScratchPool* pool);
  ScratchScope(const ScratchScope&) = delete;
  ScratchScope& operator=(const ScratchScope&) = delete;
  ~ScratchScope();

 private:
  ScratchPool* previous_;
};

/// The pool installed on this thread, or nullptr.
[[nodiscard]] ScratchPool* installed_pool();
/// Chunks made by every pool of the process so far: what shows whether a call took a pool's
/// blocks (the tests of MeshBooleanOptions::scratch_pool).
[[nodiscard]] std::size_t scratch_chunks_made();

/// A block of `bytes` (at least ScratchPool::min_bytes), aligned as operator new's: from the
/// installed pool, or from operator new when none is installed.
[[nodiscard]] void* scratch_allocate(std::size_t bytes);
/// Gives a block of scratch_allocate back to where it came from.
void scratch_deallocate(void* block) noexcept;

/// The allocator of the engine's large arrays: blocks of ScratchPool::min_bytes and more through
/// scratch_allocate, smaller ones from std::allocator. Stateless: all instances compare equal,
/// so vectors move, swap and are moved into one another as with std::allocator.
///
/// Elements made without arguments are default-initialized (DefaultInitConstruct): `resize(n)`
/// leaves new trivial elements indeterminate (a reused block holds a former array's bytes).
/// Where zeros (or any value) are wanted, say so: `assign(n, 0)`.
template <class T>
struct ScratchAllocator : DefaultInitConstruct {
  using value_type = T;
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__,
                "scratch blocks are aligned as operator new's");

  ScratchAllocator() = default;
  template <class U>
  explicit(false) ScratchAllocator(const ScratchAllocator<U>& /*other*/) noexcept {}

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > max_size()) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < ScratchPool::min_bytes) return std::allocator<T>{}.allocate(n);
    return static_cast<T*>(scratch_allocate(bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < ScratchPool::min_bytes) {
      std::allocator<T>{}.deallocate(p, n);
      return;
    }
    scratch_deallocate(p);
  }
  [[nodiscard]] static constexpr std::size_t max_size() noexcept {
    return (std::size_t{0} - 2 * ScratchPool::granule) / sizeof(T);
  }

  template <class U>
  friend bool operator==(const ScratchAllocator& /*a*/, const ScratchAllocator<U>& /*b*/) {
    return true;
  }
};

/// A vector of the engine's scratch memory (ScratchAllocator).
template <class T>
using ScratchVector = std::vector<T, ScratchAllocator<T>>;

}  // namespace contain::clip::solid
