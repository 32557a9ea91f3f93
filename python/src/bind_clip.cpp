// contain.clip_segments (the batch segment clippers) and contain.polygon_boolean.

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/core/parallel.h"
#include "contain/io/wkt.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

clip::Op parse_op(const std::string& op) {
  if (op == "intersection") return clip::Op::intersection;
  if (op == "union") return clip::Op::union_;
  if (op == "difference") return clip::Op::difference;
  if (op == "xor" || op == "symdifference") return clip::Op::xor_;
  throw py::value_error("op must be 'intersection', 'union', 'difference' or 'xor', got '" + op +
                        "'");
}

// Exactly one region keyword; its name.
const char* chosen_region(const py::handle& box, const py::handle& halfspace,
                          const py::handle& ball, const py::handle& convex) {
  int given = 0;
  const char* name = nullptr;
  for (const auto& [value, label] : {std::pair{box, "box"}, std::pair{halfspace, "halfspace"},
                                     std::pair{ball, "ball"}, std::pair{convex, "convex"}}) {
    if (!value.is_none()) {
      ++given;
      name = label;
    }
  }
  if (given != 1) {
    throw py::value_error("clip_segments: give exactly one of box=, halfspace=, ball=, convex=");
  }
  return name;
}

// Runs `clip` (which fills out and kept from the segments) without the GIL, then packs the
// answers: (N, 2 d) float64 clipped segments (NaN rows where nothing is left) and (N,) bool.
template <class Segment, class Clip>
py::tuple run(const Doubles& array, int threads, Clip&& clip) {
  const std::size_t n = static_cast<std::size_t>(array.shape(0));
  const auto* segments = reinterpret_cast<const Segment*>(array.data());
  std::vector<Segment> out(n);
  std::vector<std::uint8_t> kept(n);
  {
    py::gil_scoped_release release;
    clip(std::span<const Segment>(segments, n), std::span<Segment>(out),
         std::span<std::uint8_t>(kept), BatchOptions{.threads = threads});
  }
  constexpr py::ssize_t width = sizeof(Segment) / sizeof(double);
  std::vector<double> values(n * width);
  py::array_t<bool> flags(static_cast<py::ssize_t>(n));
  bool* f = flags.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = kept[i] != 0;
    const auto* s = reinterpret_cast<const double*>(&out[i]);
    for (py::ssize_t k = 0; k < width; ++k) {
      values[i * width + static_cast<std::size_t>(k)] =
          f[i] ? s[k] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return py::make_tuple(to_numpy(std::move(values), static_cast<py::ssize_t>(n), width), flags);
}

static_assert(sizeof(Segment3) == 6 * sizeof(double) && sizeof(Segment2) == 4 * sizeof(double));

// Clips every segment with `clip(segment) -> ClippedSegment`, without the GIL, in parallel.
template <class Segment, class One>
py::tuple run_each(const Doubles& array, int threads, One&& one) {
  return run<Segment>(array, threads, [&](auto in, auto out, auto kept, auto options) {
    parallel_for(in.size(), options, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const auto r = one(in[i]);
        kept[i] = r.kept ? 1 : 0;
        if (r.kept) out[i] = r.segment;
      }
    });
  });
}

// The segments of dimension D (Segment2 or Segment3) against the one region given.
template <int D>
py::tuple clip_dim(const Doubles& array, const py::handle& box, const py::handle& halfspace,
                   const py::handle& ball, const py::handle& convex, const std::string& algorithm,
                   int threads) {
  using Segment = std::conditional_t<D == 2, Segment2, Segment3>;
  const std::string region = chosen_region(box, halfspace, ball, convex);
  if (algorithm != "auto" && region != "box" && algorithm != "cyrus-beck") {
    throw py::value_error("algorithm='" + algorithm + "' clips by a box only");
  }
  const auto batch = [&](const auto& shape) {
    return run<Segment>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, shape, o, k, opt);
    });
  };
  if (region == "box") {
    const auto b = [&] {
      if constexpr (D == 2) {
        return to_box2(box, "box");
      } else {
        return to_box3(box, "box");
      }
    }();
    if (algorithm == "auto") return batch(b);
    if (algorithm == "cohen-sutherland") {
      return run_each<Segment>(array, threads,
                               [&](const Segment& s) { return clip::cohen_sutherland(s, b); });
    }
    if (algorithm == "liang-barsky") {
      return run_each<Segment>(array, threads,
                               [&](const Segment& s) { return clip::liang_barsky(s, b); });
    }
    const auto planes = clip::box_halfspaces(b);
    return run_each<Segment>(array, threads,
                             [&](const Segment& s) { return clip::cyrus_beck(s, planes); });
  }
  if (region == "halfspace") {
    const auto planes = [&] {
      if constexpr (D == 2) {
        return to_half_planes(halfspace, "halfspace");
      } else {
        return to_planes(halfspace, "halfspace");
      }
    }();
    if (planes.size() == 1 && algorithm == "auto") return batch(planes.front());
    return run_each<Segment>(array, threads,
                             [&](const Segment& s) { return clip::cyrus_beck(s, planes); });
  }
  if (region == "ball") {
    if (!py::isinstance<py::sequence>(ball) || py::len(ball) != 2) {
      throw py::type_error("ball must be (center, radius)");
    }
    const auto pair = py::reinterpret_borrow<py::sequence>(ball);
    const Doubles c = as_vector(pair[0], D, "ball center");
    const double radius = pair[1].cast<double>();
    require_finite(c, "ball center", 1);
    if (!std::isfinite(radius) || radius < 0) {
      fail(ErrorKind::invalid_value, "ball radius must be finite and >= 0");
    }
    if constexpr (D == 2) {
      return batch(Circle{{c.at(0), c.at(1)}, radius});
    } else {
      return batch(Sphere{{c.at(0), c.at(1), c.at(2)}, radius});
    }
  }
  if constexpr (D == 2) {
    return batch(to_convex_ring(convex, "convex ring"));
  } else {
    return batch(to_convex_polyhedron(convex, "convex"));
  }
}

}  // namespace

void bind_clip(py::module_& m) {
  m.def(
      "clip_segments",
      [](const ArrayLike& segments, const py::object& box, const py::object& halfspace,
         const py::object& ball, const py::object& convex, const std::string& algorithm,
         int threads) {
        if (algorithm != "auto" && algorithm != "cohen-sutherland" && algorithm != "liang-barsky" &&
            algorithm != "cyrus-beck") {
          throw py::value_error(
              "algorithm must be 'auto', 'cohen-sutherland', 'liang-barsky' or 'cyrus-beck', "
              "got '" +
              algorithm + "'");
        }
        py::array array = py::array::ensure(segments.object);
        if (!array) {
          PyErr_Clear();
          throw py::type_error("segments must be an (N, 4) or (N, 6) array of real numbers");
        }
        if (array.ndim() == 3 && array.shape(1) == 2 &&
            (array.shape(2) == 2 || array.shape(2) == 3)) {
          array = array.attr("reshape")(array.shape(0), 2 * array.shape(2));
        }
        const bool three = array.ndim() == 2 && array.shape(1) == 6;
        const Doubles rows = as_matrix(array, three ? 6 : 4, "segments (N, 4) for 2D or");
        require_finite(rows, "segments", threads);
        return three ? clip_dim<3>(rows, box, halfspace, ball, convex, algorithm, threads)
                     : clip_dim<2>(rows, box, halfspace, ball, convex, algorithm, threads);
      },
      "segments"_a, py::kw_only(), "box"_a = py::none(), "halfspace"_a = py::none(),
      "ball"_a = py::none(), "convex"_a = py::none(), "algorithm"_a = "auto", "threads"_a = 0,
      R"doc(
Clips every segment to a closed region; returns (clipped, kept).

segments: (N, 4) rows x0 y0 x1 y1 (2D) or (N, 6) rows x0 y0 z0 x1 y1 z1 (3D), or (N, 2, d).
Exactly one region:
  box=(min, max)            an axis-aligned box (Liang-Barsky, exact decisions)
  halfspace=(a, b, c[, d])  a x + b y [+ c z] + d >= 0 (3 numbers in 2D, 4 in 3D), or an
                            (M, 3) / (M, 4) array: the intersection (Cyrus-Beck)
  ball=(center, radius)     a closed disc / ball
  convex=...                2D: a convex ring (K, 2), either direction;
                            3D: (M, 4) planes a b c d (inside where >= 0), a convex mesh
                            (anything mesh-like) or a ConvexPolyhedron (Cyrus-Beck).
algorithm (box only): 'auto' (a branch-free batch kernel with an exact certificate),
'cohen-sutherland', 'liang-barsky' or 'cyrus-beck' (the section's algorithms one segment at a
time; the same decisions, points to rounding), as the CLI's --algorithm.
clipped: an array like segments (N, 2 d), the part left of each, in the input's direction
(zero-length when it only touches; NaN rows where nothing is left); kept: (N,) bool.
Whether a segment misses, touches or crosses is decided exactly. Runs on `threads` threads
(0: every core) without the GIL.
)doc");

  m.def(
      "polygon_boolean",
      [](const RegionLike& a, const RegionLike& b, const std::string& op,
         const std::string& fill) -> py::object {
        const MultiPolygon ra = to_region(a.object, "a");
        const MultiPolygon rb = to_region(b.object, "b");
        const clip::PolygonBooleanOptions options{.op = parse_op(op), .fill = parse_fill(fill)};
        MultiPolygon result;
        {
          py::gil_scoped_release release;
          result = clip::polygon_boolean(ra, rb, options);
        }
        if (py::isinstance<py::str>(a.object) && py::isinstance<py::str>(b.object)) {
          return py::str(io::format_wkt(result));
        }
        return py::cast(std::move(result));
      },
      "a"_a, "b"_a, "op"_a = "intersection", py::kw_only(), "fill"_a = "even_odd", R"doc(
The region `a op b`: op 'intersection', 'union', 'difference' (a minus b) or 'xor'.

a, b: Region, WKT strings, or sequences of (K, 2) rings; each read under `fill` ('even_odd'
gives the OGC meaning for valid polygons; 'nonzero', 'positive', 'negative' as Clipper2).
Returns OGC-valid polygons (shells counter-clockwise, holes clockwise) as a Region, or as WKT
when both a and b are WKT strings. Every topological decision is exact; input vertices are
kept bit for bit, crossing points are rounded (docs/clipping.md). Runs without the GIL.
)doc");
}

}  // namespace contain::python
