#include "contain/clip/polyline_clip.h"

#include <vector>

#include "clip/boolean/arrangement.h"

namespace contain::clip {

std::vector<Polyline> clip_polylines(std::span<const Polyline> polylines,
                                     std::span<const Ring> region,
                                     const PolylineClipOptions& options) {
  detail::ArrangementInput input;
  input.open_paths = true;
  input.add_rings(region, {.a = 1, .b = 0, .open = false});
  const std::size_t first_open = input.segments.size();
  std::vector<std::size_t> path_end;  // one past each polyline's last segment
  for (const Polyline& path : polylines) {
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      if (path[i] == path[i + 1]) continue;
      input.segments.push_back({path[i], path[i + 1]});
      input.labels.push_back({.a = 0, .b = 0, .open = true});
    }
    path_end.push_back(input.segments.size());
  }
  std::vector<Polyline> out;
  if (input.segments.size() == first_open) return out;
  const detail::Arrangement arrangement(input);
  const Fill fill = options.fill;
  std::size_t s = first_open;
  for (const std::size_t end : path_end) {
    Polyline current;
    auto finish = [&] {
      if (current.size() >= 2) out.push_back(std::move(current));
      current.clear();
    };
    for (; s < end; ++s) {
      for (const std::int32_t h : arrangement.pieces_of(s)) {
        const bool left = is_filled(fill, arrangement.left_a(h));
        const bool right = is_filled(fill, arrangement.left_a(h ^ 1));
        const bool in = left || right;
        if (in != (options.keep == PolylinePart::inside)) {
          finish();
          continue;
        }
        const Vec2 a = arrangement.tail_point(h), b = arrangement.head_point(h);
        if (current.empty() || current.back() != a) {
          finish();
          current.push_back(a);
        }
        current.push_back(b);
      }
    }
    finish();
  }
  return out;
}

std::vector<Polyline> clip_polylines(std::span<const Polyline> polylines,
                                     const MultiPolygon& region,
                                     const PolylineClipOptions& options) {
  const std::vector<Ring> rings = region.all_rings();
  return clip_polylines(polylines, rings, options);
}

}  // namespace contain::clip
