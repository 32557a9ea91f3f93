// MeshSlicer: a solid prepared once and sliced in blocks gives slice_mesh's sections bit for bit.

#include "contain/clip/mesh_slicer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "contain/clip/slice_mesh.h"
#include "scenes/scenes.h"

namespace contain::test {
namespace {

// The sections of values[begin, end) in blocks of `block`, one after another.
std::vector<clip::Section> sliced_in_blocks(const clip::MeshSlicer& slicer, std::size_t block,
                                            int threads) {
  std::vector<clip::Section> out;
  for (std::size_t begin = 0; begin < slicer.size(); begin += block) {
    std::vector<clip::Section> part = slicer.slice(begin, begin + block, {.threads = threads});
    for (clip::Section& s : part)
      out.push_back(std::move(s));
  }
  return out;
}

void expect_same_sections(const std::vector<clip::Section>& a,
                          const std::vector<clip::Section>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].value, b[i].value) << i;
    EXPECT_EQ(a[i].region, b[i].region) << i;
    EXPECT_EQ(a[i].triangles, b[i].triangles) << i;
  }
}

TEST(MeshSlicer, BlocksOfIncreasingPlanesAreSliceMeshsSectionsBitForBit) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  std::vector<double> values;
  for (int i = 0; i <= 60; ++i)
    values.push_back(-0.7 + 0.025 * i);
  for (const clip::Axis axis : {clip::Axis::x, clip::Axis::z}) {
    const auto whole = clip::slice_mesh(torus, values, {.axis = axis}, {.threads = 1});
    ASSERT_TRUE(whole.ok());
    const auto slicer = clip::MeshSlicer::make(torus, values, {.axis = axis});
    ASSERT_TRUE(slicer.ok());
    for (const std::size_t block : {std::size_t{1}, std::size_t{7}, std::size_t{64}}) {
      for (const int threads : {1, 2})
        expect_same_sections(sliced_in_blocks(*slicer, block, threads), *whole);
    }
  }
}

TEST(MeshSlicer, BlocksOfUnsortedAndRepeatedPlanesAreSliceMeshsSections) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  std::vector<double> values;
  for (int i = 0; i < 40; ++i)
    values.push_back(-0.7 + 0.035 * ((i * 17) % 40));
  values.push_back(values[3]);
  const auto whole = clip::slice_mesh(torus, values, {.axis = clip::Axis::y}, {.threads = 1});
  ASSERT_TRUE(whole.ok());
  const auto slicer = clip::MeshSlicer::make(torus, values, {.axis = clip::Axis::y});
  ASSERT_TRUE(slicer.ok());
  for (const std::size_t block : {std::size_t{1}, std::size_t{5}, std::size_t{100}})
    expect_same_sections(sliced_in_blocks(*slicer, block, 2), *whole);
}

// The slicer carries the sweep from one block to the next: blocks taken backwards, again, or
// skipping ahead must not inherit a wrong start.
TEST(MeshSlicer, BlocksBackwardsRepeatedOrSkippingAheadAreSliceMeshsSections) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  std::vector<double> values;
  for (int i = 0; i <= 60; ++i)
    values.push_back(-0.7 + 0.025 * i);
  const auto whole = clip::slice_mesh(torus, values, {.axis = clip::Axis::z}, {.threads = 1});
  ASSERT_TRUE(whole.ok());
  const auto slicer = clip::MeshSlicer::make(torus, values, {.axis = clip::Axis::z});
  ASSERT_TRUE(slicer.ok());
  const auto expect_block = [&](std::size_t begin, std::size_t end, int threads) {
    const std::vector<clip::Section> part = slicer->slice(begin, end, {.threads = threads});
    ASSERT_EQ(part.size(), end - begin);
    for (std::size_t i = begin; i < end; ++i) {
      EXPECT_EQ(part[i - begin].region, (*whole)[i].region) << i;
      EXPECT_EQ(part[i - begin].triangles, (*whole)[i].triangles) << i;
    }
  };
  for (int begin = 56; begin >= 0; begin -= 8) {  // backwards: 56, 48, ..., 0
    const auto b = static_cast<std::size_t>(begin);
    expect_block(b, b + 5, 2);
  }
  expect_block(20, 30, 1);
  expect_block(20, 30, 2);  // the same block again
  expect_block(45, 61, 2);  // skipping ahead
  expect_block(0, 61, 2);
}

// `slice` is const: callers on several threads share the carried sweep, each taking blocks in
// its own order (forwards, backwards, strided), and each still gets slice_mesh's sections.
TEST(MeshSlicer, ConcurrentCallersSharingTheCarriedSweepGetSliceMeshsSections) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  std::vector<double> values;
  for (int i = 0; i <= 80; ++i)
    values.push_back(-0.7 + 0.0175 * i);
  const auto whole = clip::slice_mesh(torus, values, {.axis = clip::Axis::x}, {.threads = 1});
  ASSERT_TRUE(whole.ok());
  const auto slicer = clip::MeshSlicer::make(torus, values, {.axis = clip::Axis::x});
  ASSERT_TRUE(slicer.ok());
  constexpr std::size_t kCallers = 4;
  constexpr std::size_t kBlock = 3;
  std::vector<std::vector<clip::Section>> got(kCallers, std::vector<clip::Section>(values.size()));
  std::vector<std::thread> callers;
  for (std::size_t c = 0; c < kCallers; ++c) {
    callers.emplace_back([&, c] {
      std::vector<std::size_t> begins;
      for (std::size_t b = 0; b < values.size(); b += kBlock)
        begins.push_back(b);
      if (c % 2 == 1) std::reverse(begins.begin(), begins.end());
      if (c == 2) std::rotate(begins.begin(), begins.begin() + begins.size() / 2, begins.end());
      for (int round = 0; round < 3; ++round) {
        for (const std::size_t b : begins) {
          std::vector<clip::Section> part = slicer->slice(b, b + kBlock, {.threads = 1});
          for (std::size_t i = 0; i < part.size(); ++i)
            got[c][b + i] = std::move(part[i]);
        }
      }
    });
  }
  for (std::thread& t : callers)
    t.join();
  for (const std::vector<clip::Section>& sections : got)
    expect_same_sections(sections, *whole);
}

TEST(MeshSlicer, EmptyBlocksAndRangesPastTheEndAreClamped) {
  const Mesh box = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  const std::vector<double> values{0.25, 0.5};
  const auto slicer = clip::MeshSlicer::make(box, values);
  ASSERT_TRUE(slicer.ok());
  EXPECT_EQ(slicer->size(), 2U);
  EXPECT_TRUE(slicer->slice(1, 1).empty());
  EXPECT_TRUE(slicer->slice(5, 9).empty());
  const std::vector<clip::Section> tail = slicer->slice(1, 10);
  ASSERT_EQ(tail.size(), 1U);
  EXPECT_EQ(tail[0].value, 0.5);
}

TEST(MeshSlicer, AnOpenMeshOrAValueNotFiniteIsRefused) {
  Mesh open = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  open.triangles.pop_back();
  const std::vector<double> values{0.5};
  const auto refused = clip::MeshSlicer::make(open, values);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().kind, ErrorKind::degenerate);
  const std::vector<double> bad{std::nan("")};
  const auto nan = clip::MeshSlicer::make(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}), bad);
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_value);
}

}  // namespace
}  // namespace contain::test
