#include "contain/clip/segment_region.h"

#include <cmath>
#include <string>
#include <type_traits>

#include "contain/clip/box_halfspaces.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/core/parallel.h"

#include "clip/segment_common.h"

namespace contain::clip {
namespace {

bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}
bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Whether every number that describes the region is finite.
bool finite_region(const Box2& b) {
  return finite(b.min) && finite(b.max);
}
bool finite_region(const Box3& b) {
  return finite(b.min) && finite(b.max);
}
bool finite_region(const Circle& c) {
  return finite(c.center) && std::isfinite(c.radius);
}
bool finite_region(const Sphere& s) {
  return finite(s.center) && std::isfinite(s.radius);
}
bool finite_region(const Ring& ring) {
  for (const Vec2& p : ring) {
    if (!finite(p)) return false;
  }
  return true;
}
bool finite_region(const std::vector<HalfPlane>& planes) {
  for (const HalfPlane& h : planes) {
    if (!std::isfinite(h.a) || !std::isfinite(h.b) || !std::isfinite(h.c)) return false;
  }
  return true;
}
bool finite_region(const std::vector<Plane>& planes) {
  for (const Plane& h : planes) {
    if (!std::isfinite(h.a) || !std::isfinite(h.b) || !std::isfinite(h.c) || !std::isfinite(h.d)) {
      return false;
    }
  }
  return true;
}
// A ConvexPolyhedron is validated by its constructors.
bool finite_region(const ConvexPolyhedron&) {
  return true;
}

const char* clipper_name(SegmentClipper clipper) {
  switch (clipper) {
    case SegmentClipper::automatic:
      return "automatic";
    case SegmentClipper::cohen_sutherland:
      return "cohen-sutherland";
    case SegmentClipper::liang_barsky:
      return "liang-barsky";
    case SegmentClipper::cyrus_beck:
      return "cyrus-beck";
  }
  return "unknown";
}

template <class S, class Region>
Status check(std::span<const S> segments, const Region& region, std::span<S> out,
             std::span<std::uint8_t> kept, const SegmentClipOptions& options) {
  if (out.size() != segments.size() || kept.size() != segments.size()) {
    return Error{ErrorKind::usage, "clip_segments: out has " + std::to_string(out.size()) +
                                       " and kept " + std::to_string(kept.size()) +
                                       " entries for " + std::to_string(segments.size()) +
                                       " segments; give one each"};
  }
  const bool box = region.index() == 0;
  if (!box && (options.clipper == SegmentClipper::cohen_sutherland ||
               options.clipper == SegmentClipper::liang_barsky)) {
    return Error{ErrorKind::usage, std::string("clip_segments: the ") +
                                       clipper_name(options.clipper) +
                                       " clipper clips by a box only"};
  }
  if (!std::visit([](const auto& r) { return finite_region(r); }, region)) {
    return Error{ErrorKind::invalid_value,
                 "clip_segments: the region has a number that is NaN or infinite"};
  }
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (!finite(segments[i].a) || !finite(segments[i].b)) {
      return Error{ErrorKind::invalid_value, "clip_segments: segment " + std::to_string(i) +
                                                 " has a coordinate that is NaN or infinite"};
    }
  }
  return Ok{};
}

// The box forms: the batch kernel, or one of the three textbook clippers per segment.
template <class S, class Box>
void clip_by_box(std::span<const S> in, const Box& box, std::span<S> out,
                 std::span<std::uint8_t> kept, SegmentClipper clipper, const BatchOptions& batch) {
  switch (clipper) {
    case SegmentClipper::automatic:
      clip_segments(in, box, out, kept, batch);
      return;
    case SegmentClipper::cohen_sutherland:
      detail::clip_each(in, out, kept, batch, [&](const S& s) { return cohen_sutherland(s, box); });
      return;
    case SegmentClipper::liang_barsky:
      detail::clip_each(in, out, kept, batch, [&](const S& s) { return liang_barsky(s, box); });
      return;
    case SegmentClipper::cyrus_beck: {
      const auto planes = box_halfspaces(box);
      detail::clip_each(in, out, kept, batch, [&](const S& s) { return cyrus_beck(s, planes); });
      return;
    }
  }
}

// Half-spaces: one by the exact single half-space clipper, several by Cyrus-Beck.
template <class S, class H>
void clip_by_halfspaces(std::span<const S> in, const std::vector<H>& planes, std::span<S> out,
                        std::span<std::uint8_t> kept, const BatchOptions& batch) {
  if (planes.size() == 1) {
    clip_segments(in, planes.front(), out, kept, batch);
    return;
  }
  detail::clip_each(in, out, kept, batch,
                    [&](const S& s) { return cyrus_beck(s, std::span<const H>(planes)); });
}

template <class S, class Region>
Status clip_by_region(std::span<const S> segments, const Region& region, std::span<S> out,
                      std::span<std::uint8_t> kept, const SegmentClipOptions& options,
                      const BatchOptions& batch) {
  if (Status valid = check(segments, region, out, kept, options); !valid) return valid;
  std::visit(
      [&](const auto& r) {
        using R = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<R, Box2> || std::is_same_v<R, Box3>) {
          clip_by_box(segments, r, out, kept, options.clipper, batch);
        } else if constexpr (std::is_same_v<R, std::vector<HalfPlane>> ||
                             std::is_same_v<R, std::vector<Plane>>) {
          clip_by_halfspaces(segments, r, out, kept, batch);
        } else {
          clip_segments(segments, r, out, kept, batch);  // convex region, disc or ball
        }
      },
      region);
  return Ok{};
}

}  // namespace

Status clip_segments(std::span<const Segment2> segments, const SegmentRegion2& region,
                     std::span<Segment2> out, std::span<std::uint8_t> kept,
                     const SegmentClipOptions& options, const BatchOptions& batch) {
  return clip_by_region(segments, region, out, kept, options, batch);
}

Status clip_segments(std::span<const Segment3> segments, const SegmentRegion3& region,
                     std::span<Segment3> out, std::span<std::uint8_t> kept,
                     const SegmentClipOptions& options, const BatchOptions& batch) {
  return clip_by_region(segments, region, out, kept, options, batch);
}

}  // namespace contain::clip
