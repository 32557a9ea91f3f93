// Batch forms: the branch-free box kernel decides exactly as the exact Liang-Barsky, whatever
// the thread count; every vector version of the kernel is the scalar kernel bit for bit; the
// other regions match their one-shot clippers.

#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

#include "clip/box_kernel.h"
#include "clip/segment_common.h"
#include "clip/segment_oracle.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/clip/segment_sphere.h"

namespace contain::test {
namespace {

TEST(ClipSegments, BoxKernelDecidesExactlyAsLiangBarskyOnDegenerateInput) {
  SegmentGenerator gen(23);
  std::vector<Segment3> in(30000);
  for (auto& s : in)
    s = gen.segment3();
  // Tiny and huge coordinates send segments to the exact path too.
  in[0] = {{1e-310, 0, 0}, {2e-310, 0, 0}};
  in[1] = {{-1e305, 0.5, 0.5}, {1e305, 0.5, 0.5}};
  const Box3 box{{-1, -1, -1}, {1, 1, 1}};
  for (int threads : {1, 2, 3}) {
    std::vector<Segment3> out(in.size());
    std::vector<std::uint8_t> kept(in.size());
    clip::clip_segments(in, box, out, kept, {.threads = threads});
    for (std::size_t i = 0; i < in.size(); ++i) {
      const auto r = clip::liang_barsky(in[i], box);
      ASSERT_EQ(kept[i], r.kept ? 1 : 0) << i;
      if (!r.kept) continue;
      EXPECT_TRUE(box.contains(out[i].a) && box.contains(out[i].b)) << i;
      EXPECT_EQ(out[i].a == out[i].b, r.segment.a == r.segment.b) << i;
      EXPECT_NEAR(out[i].a.x, r.segment.a.x, 1e-14 * 2e305);
      if (i > 1) {
        EXPECT_NEAR(out[i].a.y, r.segment.a.y, 1e-14) << i;
        EXPECT_NEAR(out[i].b.z, r.segment.b.z, 1e-14) << i;
      }
    }
  }
}

TEST(ClipSegments, Box2DKernelMatchesLiangBarsky) {
  SegmentGenerator gen(29);
  std::vector<Segment2> in(20000);
  for (auto& s : in)
    s = gen.segment2();
  const Box2 box{{-1, -0.5}, {1, 1}};
  std::vector<Segment2> out(in.size());
  std::vector<std::uint8_t> kept(in.size());
  clip::clip_segments(in, box, out, kept);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::liang_barsky(in[i], box);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0) << i;
    if (r.kept) {
      EXPECT_NEAR(out[i].b.x, r.segment.b.x, 1e-14);
    }
  }
}

// Segments rich in degenerate positions, with the kernel's unsure cases among them.
template <class S>
std::vector<S> kernel_input(unsigned seed, std::size_t n) {
  SegmentGenerator gen(seed);
  std::vector<S> in(n);
  for (auto& s : in) {
    if constexpr (std::is_same_v<S, Segment3>) {
      s = gen.segment3();
    } else {
      s = gen.segment2();
    }
  }
  if (n > 3) {
    in[1].a.x = 1e-310;
    in[1].b.x = 2e-310;
    in[2].a.x = -1e305;
    in[3].b = in[3].a;
  }
  return in;
}

std::vector<clip::detail::KernelIsa> available_isas() {
  std::vector<clip::detail::KernelIsa> isas;
  for (auto isa : {clip::detail::KernelIsa::portable, clip::detail::KernelIsa::avx2})
    if (clip::detail::kernel_isa_available(isa)) isas.push_back(isa);
  return isas;
}

template <int D, class S, class Box>
void expect_kernel_versions_equal_scalar(const std::vector<S>& in, const Box& box) {
  clip::detail::KernelBox<D> kb{};
  for (int k = 0; k < D; ++k) {
    kb.min[k] = clip::detail::coord(box.min, k);
    kb.max[k] = clip::detail::coord(box.max, k);
  }
  std::vector<S> want(in.size());
  std::vector<std::uint8_t> want_flags(in.size());
  clip::detail::box_kernel_scalar<D>(reinterpret_cast<const double*>(in.data()),
                                     reinterpret_cast<double*>(want.data()), want_flags.data(),
                                     in.size(), kb);
  for (auto isa : available_isas()) {
    std::vector<S> got(in.size());
    std::vector<std::uint8_t> flags(in.size());
    clip::detail::run_box_kernel(in, box, got, flags, isa);
    for (std::size_t i = 0; i < in.size(); ++i) {
      ASSERT_EQ(flags[i], want_flags[i]) << i << " isa " << static_cast<int>(isa);
      // Sure keeps are final: their points must be the scalar kernel's, bit for bit.
      if (flags[i] == 1) {
        EXPECT_EQ(std::memcmp(&got[i], &want[i], sizeof(S)), 0)
            << i << " isa " << static_cast<int>(isa);
      }
    }
  }
}

TEST(ClipSegments, EveryKernelVersionIsTheScalarKernelBitForBit) {
  // Sizes around the lane counts exercise the scalar tails too.
  for (std::size_t n : {1, 2, 3, 4, 5, 7, 9, 4001}) {
    expect_kernel_versions_equal_scalar<3>(kernel_input<Segment3>(41 + n, n),
                                           Box3{{-1, -1, -1}, {1, 1, 1}});
    expect_kernel_versions_equal_scalar<3>(kernel_input<Segment3>(43 + n, n),
                                           Box3{{-1, 0, -0.5}, {1, 0, 2}});
    expect_kernel_versions_equal_scalar<2>(kernel_input<Segment2>(47 + n, n),
                                           Box2{{-1, -0.5}, {1, 1}});
  }
}

TEST(ClipSegments, EveryKernelVersionDecidesExactlyAndGivesTheSamePoints) {
  const auto in = kernel_input<Segment3>(53, 20001);
  const Box3 box{{-1, -1, -1}, {1, 1, 1}};
  std::vector<Segment3> first;
  for (auto isa : available_isas()) {
    std::vector<Segment3> out(in.size());
    std::vector<std::uint8_t> kept(in.size());
    clip::detail::clip_segments_with(in, box, out, kept, {.threads = 2}, isa);
    for (std::size_t i = 0; i < in.size(); ++i) {
      ASSERT_EQ(kept[i], clip::liang_barsky(in[i], box).kept ? 1 : 0) << i;
      if (!kept[i]) out[i] = {};
    }
    if (first.empty()) {
      first = out;
    } else {
      EXPECT_EQ(std::memcmp(first.data(), out.data(), out.size() * sizeof(Segment3)), 0);
    }
  }
}

TEST(ClipSegments, OtherRegionsMatchTheOneShotClippers) {
  SegmentGenerator gen(31);
  std::vector<Segment3> in(3000);
  for (auto& s : in)
    s = gen.segment3();
  std::vector<Segment3> out(in.size());
  std::vector<std::uint8_t> kept(in.size());
  const Sphere ball{{0, 0, 0}, 1};
  clip::clip_segments(in, ball, out, kept, {.threads = 2});
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::clip_segment(in[i], ball);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0);
    if (r.kept) {
      EXPECT_EQ(out[i], r.segment);
    }
  }
  const auto poly = ConvexPolyhedron::from_planes({{1, 1, 0, 1}, {-1, 0, 0, 1}, {0, -1, 1, 1}});
  ASSERT_TRUE(poly.ok());
  clip::clip_segments(in, *poly, out, kept, {.threads = 2});
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::cyrus_beck(in[i], *poly);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0);
    if (r.kept) {
      EXPECT_EQ(out[i], r.segment);
    }
  }
}

// A short `out` or `kept` is a programming error (core/parallel.h's batch rule): an assertion in
// builds that check them; elsewhere the common prefix is clipped and nothing is written past a
// span (the sentinel beyond the short spans stays).
TEST(ClipSegments, ASpanShorterThanTheSegmentsIsAssertedOrCutToThePrefix) {
  const std::vector<Segment2> in(4, Segment2{{-1, 0.5}, {2, 0.5}});
  EXPECT_DEBUG_DEATH(
      {
        std::vector<Segment2> out(4);
        std::vector<std::uint8_t> kept(4, 7);
        clip::clip_segments(in, Box2{{0, 0}, {1, 1}}, std::span<Segment2>(out).first(4),
                            std::span<std::uint8_t>(kept).first(3));
        EXPECT_EQ(kept, (std::vector<std::uint8_t>{1, 1, 1, 7}));
        clip::clip_segments(in, Circle{{0, 0}, 1}, std::span<Segment2>(out).first(2),
                            std::span<std::uint8_t>(kept).first(4));
        EXPECT_EQ(kept[3], 7);
      },
      "inputs' size");
}

}  // namespace
}  // namespace contain::test
