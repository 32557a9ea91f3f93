// The mesh boolean's scratch memory (scratch.h). Each block starts with a header naming its
// chunk (none for a block of operator new) and its bytes, so that a block goes back to the pool
// it came from, or to the heap, whichever pool is installed when it is freed; a chunk whose pool
// is gone is freed with its last block.

#include "clip/solid/scratch.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <new>
#include <utility>

namespace contain::clip::solid {

namespace detail {

struct ScratchChunk {
  std::byte* memory;
  std::size_t bytes;
  std::size_t high_water = 0;  // the highest end of a block it held
  std::size_t blocks = 0;      // held now
  ScratchPool* pool;           // nullptr once the pool is gone (blocks still held)
};

}  // namespace detail

namespace {

using detail::ScratchChunk;

struct Header {
  ScratchChunk* chunk;  // nullptr: a block of operator new
  std::size_t bytes;    // of the block, header included
};
// The header keeps the block after it aligned as operator new's blocks are.
constexpr std::size_t header_bytes = __STDCPP_DEFAULT_NEW_ALIGNMENT__;
static_assert(sizeof(Header) <= header_bytes);
constexpr std::align_val_t chunk_alignment{ScratchPool::granule};

thread_local ScratchPool* installed = nullptr;
std::atomic<std::size_t> chunks_made{0};

void free_chunk(ScratchChunk* c) noexcept {
  ::operator delete(c->memory, chunk_alignment);
  delete c;
}

Header* header_of(void* block) {
  return reinterpret_cast<Header*>(static_cast<std::byte*>(block) - header_bytes);
}

}  // namespace

ScratchPool::~ScratchPool() {
  for (ScratchChunk* c : chunks_) {
    if (c->blocks == 0) {
      free_chunk(c);
    } else {
      c->pool = nullptr;  // freed with its last block (scratch_deallocate)
    }
  }
}

std::pair<ScratchChunk*, std::size_t> ScratchPool::acquire(std::size_t bytes) {
  // Room for the ranges first, so that release never allocates: a free range ends at a block or
  // at its chunk's end, so there are at most as many as blocks and chunks.
  free_.reserve(blocks_ + 1 + chunks_.size() + 1);
  // Address-ordered first fit, oldest chunk first: the pages written before are taken again
  // before any fresh one.
  const auto fit =
      std::find_if(free_.begin(), free_.end(), [&](const Free& f) { return f.bytes >= bytes; });
  std::size_t chunk = 0, offset = 0;
  if (fit != free_.end()) {
    chunk = fit->chunk;
    offset = fit->offset;
    if (fit->bytes == bytes) {
      free_.erase(fit);
    } else {
      fit->offset += bytes;
      fit->bytes -= bytes;
    }
  } else {
    // A new chunk, at least as large as all before (their number stays logarithmic).
    const std::size_t size =
        (std::max({bytes, min_chunk, reserved_bytes()}) + granule - 1) / granule * granule;
    chunks_.reserve(chunks_.size() + 1);
    auto* memory = static_cast<std::byte*>(::operator new(size, chunk_alignment));
    try {
      chunks_.push_back(new ScratchChunk{memory, size, 0, 0, this});
      chunks_made.fetch_add(1, std::memory_order_relaxed);
    } catch (...) {
      ::operator delete(memory, chunk_alignment);
      throw;
    }
    chunk = chunks_.size() - 1;
    if (size > bytes) free_.push_back({chunk, bytes, size - bytes});
  }
  ScratchChunk* c = chunks_[chunk];
  c->high_water = std::max(c->high_water, offset + bytes);
  ++c->blocks;
  ++blocks_;
  used_ += bytes;
  return {c, offset};
}

void ScratchPool::release(ScratchChunk* c, std::size_t offset, std::size_t bytes) noexcept {
  const auto chunk =
      static_cast<std::size_t>(std::find(chunks_.begin(), chunks_.end(), c) - chunks_.begin());
  --c->blocks;
  --blocks_;
  used_ -= bytes;
  const auto after = std::lower_bound(
      free_.begin(), free_.end(), Free{chunk, offset, bytes}, [](const Free& a, const Free& b) {
        return a.chunk != b.chunk ? a.chunk < b.chunk : a.offset < b.offset;
      });
  const bool joins_before = after != free_.begin() && (after - 1)->chunk == chunk &&
                            (after - 1)->offset + (after - 1)->bytes == offset;
  const bool joins_after =
      after != free_.end() && after->chunk == chunk && offset + bytes == after->offset;
  if (joins_before && joins_after) {
    (after - 1)->bytes += bytes + after->bytes;
    free_.erase(after);
  } else if (joins_before) {
    (after - 1)->bytes += bytes;
  } else if (joins_after) {
    after->offset = offset;
    after->bytes += bytes;
  } else {
    // Room for it was reserved by acquire: this insert does not allocate.
    free_.insert(after, Free{chunk, offset, bytes});
  }
}

std::size_t ScratchPool::reserved_bytes() const {
  std::size_t sum = 0;
  for (const ScratchChunk* c : chunks_)
    sum += c->bytes;
  return sum;
}

std::size_t ScratchPool::high_water_bytes() const {
  std::size_t sum = 0;
  for (const ScratchChunk* c : chunks_)
    sum += c->high_water;
  return sum;
}

ScratchScope::ScratchScope(ScratchPool& pool) : ScratchScope(&pool) {}

ScratchScope::ScratchScope(ScratchPool* pool) : previous_(std::exchange(installed, pool)) {}

ScratchScope::~ScratchScope() {
  installed = previous_;
}

ScratchPool* installed_pool() {
  return installed;
}

std::size_t scratch_chunks_made() {
  return chunks_made.load(std::memory_order_relaxed);
}

void* scratch_allocate(std::size_t bytes) {
  const std::size_t total = (header_bytes + bytes + ScratchPool::granule - 1) /
                            ScratchPool::granule * ScratchPool::granule;
  std::byte* at = nullptr;
  ScratchChunk* chunk = nullptr;
  if (installed != nullptr) {
    const auto [c, offset] = installed->acquire(total);
    chunk = c;
    at = c->memory + offset;
  } else {
    at = static_cast<std::byte*>(::operator new(total));
  }
  ::new (static_cast<void*>(at)) Header{chunk, total};
  return at + header_bytes;
}

void scratch_deallocate(void* block) noexcept {
  if (block == nullptr) return;
  const Header h = *header_of(block);
  auto* at = static_cast<std::byte*>(block) - header_bytes;
  if (h.chunk == nullptr) {
    ::operator delete(at);
  } else if (h.chunk->pool != nullptr) {
    h.chunk->pool->release(h.chunk, static_cast<std::size_t>(at - h.chunk->memory), h.bytes);
  } else if (--h.chunk->blocks == 0) {
    free_chunk(h.chunk);
  }
}

}  // namespace contain::clip::solid
