// The mesh boolean's scratch memory (clip/solid/scratch.h): blocks of a call's pool are reused
// where freed (same address, neighbours joined), never overlap while alive, are aligned, are not
// zeroed, go back to the pool they came from whichever is installed, outlive their pool safely;
// small blocks and blocks made with no pool installed are the heap's. And mesh_boolean owns its
// pool: it leaves the caller's installed pool as it found it.

#include "clip/solid/scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "clip/solid/solid_oracle.h"
#include "contain/clip/mesh_boolean.h"

namespace contain::test {
namespace {

using clip::solid::installed_pool;
using clip::solid::scratch_chunks_made;
using clip::solid::ScratchPool;
using clip::solid::ScratchScope;
using clip::solid::ScratchVector;
using Bytes = ScratchVector<std::uint8_t>;

constexpr std::size_t large = ScratchPool::min_bytes;  // the least block the pool serves

std::uintptr_t address(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p);
}

TEST(ScratchPool, WithoutAPoolBlocksAreTheHeaps) {
  ASSERT_EQ(installed_pool(), nullptr);
  Bytes v(4 * large, 7);
  EXPECT_EQ(v.front(), 7);
  EXPECT_EQ(v.back(), 7);
  v.resize(8 * large, 9);  // a larger heap block, the old one freed to the heap
  EXPECT_EQ(v[4 * large - 1], 7);
  EXPECT_EQ(v.back(), 9);
}

TEST(ScratchPool, AFreedBlockIsTakenAgainAtItsAddress) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  std::uintptr_t first = 0;
  {
    const Bytes v(3 * large, 1);
    first = address(v.data());
    EXPECT_GE(pool.used_bytes(), 3 * large);
  }
  EXPECT_EQ(pool.used_bytes(), 0U);
  const std::size_t high = pool.high_water_bytes();
  const Bytes w(3 * large, 2);
  EXPECT_EQ(address(w.data()), first);
  EXPECT_EQ(pool.high_water_bytes(), high);  // no page beyond those written before
  EXPECT_EQ(pool.chunks(), 1U);
}

TEST(ScratchPool, FreedNeighboursJoinForALargerBlock) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  std::optional<Bytes> a(std::in_place, 2 * large, 1);
  std::optional<Bytes> b(std::in_place, 2 * large, 2);
  const Bytes guard(large, 3);  // keeps the range after b taken
  const std::uintptr_t at = address(a->data());
  ASSERT_LT(at, address(b->data()));
  a.reset();
  b.reset();
  // Neither range alone holds it (each is 2 large + a page: the header rounded up); the two
  // joined do.
  const Bytes c(4 * large, 4);
  EXPECT_EQ(address(c.data()), at);
  EXPECT_LT(address(c.data()), address(guard.data()));
}

TEST(ScratchPool, LiveBlocksNeverOverlapAndKeepTheirBytes) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  std::mt19937 rng(25);
  std::uniform_int_distribution<std::size_t> size(large, 16 * large);
  std::vector<std::pair<std::unique_ptr<Bytes>, std::uint8_t>> live;
  for (int step = 0; step < 400; ++step) {
    if (!live.empty() && rng() % 3 == 0) {
      const std::size_t k = rng() % live.size();
      const auto& [v, mark] = live[k];
      ASSERT_TRUE(std::all_of(v->begin(), v->end(), [m = mark](std::uint8_t x) { return x == m; }))
          << "step " << step;
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(k));
      continue;
    }
    const auto mark = static_cast<std::uint8_t>(step);
    auto v = std::make_unique<Bytes>(size(rng), mark);
    EXPECT_EQ(address(v->data()) % __STDCPP_DEFAULT_NEW_ALIGNMENT__, 0U);
    for (const auto& [u, m] : live) {
      const bool apart = address(v->data()) + v->size() <= address(u->data()) ||
                         address(u->data()) + u->size() <= address(v->data());
      ASSERT_TRUE(apart) << "step " << step;
    }
    live.emplace_back(std::move(v), mark);
  }
  for (const auto& [v, mark] : live)
    EXPECT_TRUE(std::all_of(v->begin(), v->end(), [m = mark](std::uint8_t x) { return x == m; }));
  live.clear();
  EXPECT_EQ(pool.used_bytes(), 0U);
}

TEST(ScratchPool, AlignedForEveryElementType) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  struct alignas(16) Wide {
    double a, b;
  };
  const ScratchVector<Wide> w(large / sizeof(Wide) + 3);
  const ScratchVector<std::uint8_t> odd(large + 1);
  const ScratchVector<Wide> w2(large / sizeof(Wide) + 5);
  EXPECT_EQ(address(w.data()) % alignof(Wide), 0U);
  EXPECT_EQ(address(w2.data()) % alignof(Wide), 0U);
  EXPECT_EQ(address(odd.data()) % __STDCPP_DEFAULT_NEW_ALIGNMENT__, 0U);
}

TEST(ScratchPool, ResizeLeavesAReusedBlockUnzeroed) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  std::uintptr_t first = 0;
  {
    const Bytes v(2 * large, 0xab);
    first = address(v.data());
  }
  Bytes w;
  w.resize(2 * large);  // default-initialized: the former array's bytes, not zeros
  ASSERT_EQ(address(w.data()), first);
  EXPECT_TRUE(std::all_of(w.begin(), w.end(), [](std::uint8_t x) { return x == 0xab; }));
  w.assign(w.size(), 0);  // zeros where asked for
  EXPECT_TRUE(std::all_of(w.begin(), w.end(), [](std::uint8_t x) { return x == 0; }));
}

TEST(ScratchPool, SmallBlocksStayOnTheHeap) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  const Bytes small(large - 1, 5);
  EXPECT_EQ(pool.used_bytes(), 0U);
  EXPECT_EQ(pool.chunks(), 0U);
  const Bytes big(large, 5);
  EXPECT_GE(pool.used_bytes(), large);
  EXPECT_EQ(pool.chunks(), 1U);
}

TEST(ScratchPool, ABlockLargerThanAChunkGetsAChunkOfItsOwn) {
  ScratchPool pool;
  const ScratchScope scope(pool);
  const Bytes a(large, 1);
  const Bytes huge(ScratchPool::min_chunk + large, 2);
  EXPECT_EQ(pool.chunks(), 2U);
  EXPECT_GE(pool.reserved_bytes(), ScratchPool::min_chunk + ScratchPool::min_chunk + large);
  EXPECT_EQ(huge.back(), 2);
}

TEST(ScratchPool, BlocksGoBackToThePoolTheyCameFrom) {
  ScratchPool outer;
  const ScratchScope outer_scope(outer);
  std::optional<Bytes> from_outer(std::in_place, 2 * large, 1);
  const std::size_t outer_used = outer.used_bytes();
  {
    ScratchPool inner;
    const ScratchScope inner_scope(inner);
    EXPECT_EQ(installed_pool(), &inner);
    const Bytes from_inner(large, 2);
    EXPECT_EQ(outer.used_bytes(), outer_used);  // made by the installed pool only
    EXPECT_GE(inner.used_bytes(), large);
    from_outer.reset();  // freed while inner is installed: back to outer
    EXPECT_EQ(outer.used_bytes(), 0U);
    EXPECT_GE(inner.used_bytes(), large);
  }
  EXPECT_EQ(installed_pool(), &outer);
}

TEST(ScratchPool, ABlockMayOutliveItsPool) {
  std::optional<Bytes> survivor;
  {
    ScratchPool pool;
    const ScratchScope scope(pool);
    survivor.emplace(3 * large, 6);
    const Bytes gone(large, 7);
  }
  EXPECT_EQ(installed_pool(), nullptr);
  // Its chunk stays until it is freed (a sanitizer build would report a use after free here).
  EXPECT_TRUE(
      std::all_of(survivor->begin(), survivor->end(), [](std::uint8_t x) { return x == 6; }));
  (*survivor)[0] = 8;
  survivor.reset();
}

// The two spheres' engine arrays of 128 kB and more (the pairs' work, the point store, ...)
// come from a pool of the call's own: it makes chunks, takes none from a pool installed by the
// caller, and restores the caller's.
TEST(ScratchPool, MeshBooleanOwnsItsPool) {
  const std::vector<Mesh> in = {icosphere(5, 1.0, {0, 0, 0}), icosphere(5, 1.0, {0.5, 0.5, 0.5})};
  const std::size_t before_alone = scratch_chunks_made();
  const Result<clip::MeshBooleanResult> alone = clip::mesh_boolean(in);
  ASSERT_TRUE(alone);
  EXPECT_GT(scratch_chunks_made(), before_alone);  // its own pool made chunks
  ScratchPool outer;
  const ScratchScope scope(outer);
  const Result<clip::MeshBooleanResult> nested = clip::mesh_boolean(in);
  ASSERT_TRUE(nested);
  EXPECT_EQ(installed_pool(), &outer);  // restored
  EXPECT_EQ(outer.chunks(), 0U);        // the call used a pool of its own
  EXPECT_TRUE(nested->mesh == alone->mesh);
}

// Without its pool (the CLI, whose heap keeps freed memory) the call makes no chunk and takes
// none of an installed pool's blocks: its arrays are on the heap; the mesh is the same.
TEST(ScratchPool, MeshBooleanWithoutItsPoolTakesNoPoolsBlocksAndWritesTheSameMesh) {
  const std::vector<Mesh> in = {icosphere(5, 1.0, {0, 0, 0}), icosphere(5, 1.0, {0.5, 0.5, 0.5})};
  const Result<clip::MeshBooleanResult> pooled = clip::mesh_boolean(in);
  ASSERT_TRUE(pooled);
  ScratchPool outer;
  const ScratchScope scope(outer);
  const std::size_t before = scratch_chunks_made();
  const Result<clip::MeshBooleanResult> heap =
      clip::mesh_boolean(in, {.op = clip::Op::union_, .scratch_pool = false});
  ASSERT_TRUE(heap);
  EXPECT_EQ(scratch_chunks_made(), before);  // no pool made a chunk
  EXPECT_EQ(installed_pool(), &outer);       // restored
  EXPECT_EQ(outer.chunks(), 0U);             // nothing from the installed pool either
  EXPECT_TRUE(heap->mesh == pooled->mesh);
  EXPECT_EQ(heap->shells, pooled->shells);
  EXPECT_EQ(heap->volume, pooled->volume);
}

}  // namespace
}  // namespace contain::test
