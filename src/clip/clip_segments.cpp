#include "contain/clip/clip_segments.h"

#include <type_traits>

#include "clip/box_exact.h"
#include "clip/box_kernel.h"
#include "clip/convex_functions.h"
#include "clip/cyrus_beck_impl.h"
#include "contain/clip/segment_halfspace.h"
#include "contain/clip/segment_sphere.h"

namespace contain::clip {
namespace {

static_assert(sizeof(Segment3) == 6 * sizeof(double) && std::is_standard_layout_v<Segment3>);
static_assert(sizeof(Segment2) == 4 * sizeof(double) && std::is_standard_layout_v<Segment2>);

// The batch rule of core/parallel.h: `out` and `kept` have the segments' size (asserted; a
// build without assertions clips the common prefix and never writes past a span).
template <class S>
void common_size(std::span<const S>& s, std::span<S>& out, std::span<std::uint8_t>& kept) {
  const std::size_t n = batch_size(batch_size(s.size(), out.size()), kept.size());
  s = s.first(n);
  out = out.first(n);
  kept = kept.first(n);
}

template <int D, class Box>
detail::KernelBox<D> kernel_box(const Box& box) {
  detail::KernelBox<D> kb{};
  for (int k = 0; k < D; ++k) {
    kb.min[k] = detail::coord(box.min, k);
    kb.max[k] = detail::coord(box.max, k);
  }
  return kb;
}

template <int D, class S, class Box>
void box_batch(std::span<const S> segments, const Box& box, std::span<S> out,
               std::span<std::uint8_t> kept, const BatchOptions& options,
               detail::BoxKernel<D> kernel) {
  if (box.empty()) {
    for (auto& k : kept)
      k = 0;
    return;
  }
  const detail::KernelBox<D> kb = kernel_box<D>(box);
  parallel_for(segments.size(), options, [&](std::size_t begin, std::size_t end) {
    // Blocks keep the fallback pass in cache.
    constexpr std::size_t block = 2048;
    for (std::size_t b = begin; b < end; b += block) {
      const std::size_t n = std::min(block, end - b);
      kernel(reinterpret_cast<const double*>(segments.data() + b),
             reinterpret_cast<double*>(out.data() + b), kept.data() + b, n, kb);
      for (std::size_t i = b; i < b + n; ++i) {
        if (kept[i] < 2) continue;
        const auto r = detail::liang_barsky_exact(segments[i].a, segments[i].b, box);
        kept[i] = r.kept ? 1 : 0;
        if (r.kept) out[i] = r.segment;
      }
    }
  });
}

template <int D, class S, class Box>
void raw_kernel(std::span<const S> segments, const Box& box, std::span<S> out,
                std::span<std::uint8_t> flags, detail::KernelIsa isa) {
  detail::box_kernel_for<D>(isa)(reinterpret_cast<const double*>(segments.data()),
                                 reinterpret_cast<double*>(out.data()), flags.data(),
                                 segments.size(), kernel_box<D>(box));
}

}  // namespace

void clip_segments(std::span<const Segment3> s, const Box3& box, std::span<Segment3> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  box_batch<3>(s, box, out, kept, options, detail::best_box_kernel<3>());
}
void clip_segments(std::span<const Segment2> s, const Box2& box, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  box_batch<2>(s, box, out, kept, options, detail::best_box_kernel<2>());
}
void clip_segments(std::span<const Segment3> s, const Plane& h, std::span<Segment3> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  detail::clip_each(s, out, kept, options, [&](const Segment3& x) { return clip_segment(x, h); });
}
void clip_segments(std::span<const Segment2> s, const HalfPlane& h, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  detail::clip_each(s, out, kept, options, [&](const Segment2& x) { return clip_segment(x, h); });
}
void clip_segments(std::span<const Segment3> s, const Sphere& ball, std::span<Segment3> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  detail::clip_each(s, out, kept, options,
                    [&](const Segment3& x) { return clip_segment(x, ball); });
}
void clip_segments(std::span<const Segment2> s, const Circle& disc, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  detail::clip_each(s, out, kept, options,
                    [&](const Segment2& x) { return clip_segment(x, disc); });
}
void clip_segments(std::span<const Segment3> s, const ConvexPolyhedron& polyhedron,
                   std::span<Segment3> out, std::span<std::uint8_t> kept,
                   const BatchOptions& options) {
  common_size(s, out, kept);
  if (!polyhedron.faces().empty()) {
    const auto f = detail::face_functions(polyhedron.faces());
    detail::clip_each(s, out, kept, options, [&](const Segment3& x) {
      return detail::cyrus_beck_clip<Vec3, predicates::FaceFunction>(x.a, x.b, f);
    });
    return;
  }
  const auto f = detail::plane_functions(polyhedron.planes());
  detail::clip_each(s, out, kept, options, [&](const Segment3& x) {
    return detail::cyrus_beck_clip<Vec3, predicates::PlaneFunction>(x.a, x.b, f);
  });
}
void clip_segments(std::span<const Segment2> s, const Ring& convex_ring, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options) {
  common_size(s, out, kept);
  const auto edges = detail::edge_functions(convex_ring);
  if (!edges) {
    for (auto& k : kept)
      k = 0;
    return;
  }
  detail::clip_each(s, out, kept, options, [&](const Segment2& x) {
    return detail::cyrus_beck_clip<Vec2, predicates::EdgeFunction>(x.a, x.b, *edges);
  });
}

namespace detail {
void clip_segments_with(std::span<const Segment3> s, const Box3& box, std::span<Segment3> out,
                        std::span<std::uint8_t> kept, const BatchOptions& options, KernelIsa isa) {
  box_batch<3>(s, box, out, kept, options, box_kernel_for<3>(isa));
}
void clip_segments_with(std::span<const Segment2> s, const Box2& box, std::span<Segment2> out,
                        std::span<std::uint8_t> kept, const BatchOptions& options, KernelIsa isa) {
  box_batch<2>(s, box, out, kept, options, box_kernel_for<2>(isa));
}
void run_box_kernel(std::span<const Segment3> s, const Box3& box, std::span<Segment3> out,
                    std::span<std::uint8_t> flags, KernelIsa isa) {
  raw_kernel<3>(s, box, out, flags, isa);
}
void run_box_kernel(std::span<const Segment2> s, const Box2& box, std::span<Segment2> out,
                    std::span<std::uint8_t> flags, KernelIsa isa) {
  raw_kernel<2>(s, box, out, flags, isa);
}
}  // namespace detail

}  // namespace contain::clip
