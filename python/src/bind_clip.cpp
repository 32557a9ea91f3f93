// contain.clip_segments (the batch segment clippers) and contain.polygon_boolean.

#include <pybind11/stl.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/polygon_boolean.h"
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

py::tuple clip3(const Doubles& array, const py::handle& box, const py::handle& halfspace,
                const py::handle& ball, const py::handle& convex, int threads) {
  const std::string region = chosen_region(box, halfspace, ball, convex);
  if (region == "box") {
    const py::sequence pair = box.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("box must be (min, max)");
    const Doubles lo = as_vector(pair[0], 3, "box min"), hi = as_vector(pair[1], 3, "box max");
    const Box3 b{{lo.at(0), lo.at(1), lo.at(2)}, {hi.at(0), hi.at(1), hi.at(2)}};
    return run<Segment3>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, b, o, k, opt);
    });
  }
  if (region == "halfspace") {
    const Doubles c = as_vector(halfspace, 4, "halfspace");
    const Plane p{c.at(0), c.at(1), c.at(2), c.at(3)};
    return run<Segment3>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, p, o, k, opt);
    });
  }
  if (region == "ball") {
    const py::sequence pair = ball.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("ball must be (center, radius)");
    const Doubles c = as_vector(pair[0], 3, "ball center");
    const Sphere sphere{{c.at(0), c.at(1), c.at(2)}, pair[1].cast<double>()};
    return run<Segment3>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, sphere, o, k, opt);
    });
  }
  std::vector<Plane> planes;
  if (py::isinstance<Mesh>(convex)) {
    const auto polyhedron = take(ConvexPolyhedron::from_mesh(convex.cast<const Mesh&>()));
    return run<Segment3>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, polyhedron, o, k, opt);
    });
  }
  const Doubles rows = as_matrix(convex, 4, "convex planes");
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    const double* r = rows.data() + 4 * i;
    planes.push_back({r[0], r[1], r[2], r[3]});
  }
  const auto polyhedron = take(ConvexPolyhedron::from_planes(std::move(planes)));
  return run<Segment3>(array, threads, [&](auto s, auto o, auto k, auto opt) {
    clip::clip_segments(s, polyhedron, o, k, opt);
  });
}

py::tuple clip2(const Doubles& array, const py::handle& box, const py::handle& halfspace,
                const py::handle& ball, const py::handle& convex, int threads) {
  const std::string region = chosen_region(box, halfspace, ball, convex);
  if (region == "box") {
    const py::sequence pair = box.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("box must be (min, max)");
    const Doubles lo = as_vector(pair[0], 2, "box min"), hi = as_vector(pair[1], 2, "box max");
    const Box2 b{{lo.at(0), lo.at(1)}, {hi.at(0), hi.at(1)}};
    return run<Segment2>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, b, o, k, opt);
    });
  }
  if (region == "halfspace") {
    const Doubles c = as_vector(halfspace, 3, "halfspace");
    const HalfPlane p{c.at(0), c.at(1), c.at(2)};
    return run<Segment2>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, p, o, k, opt);
    });
  }
  if (region == "ball") {
    const py::sequence pair = ball.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("ball must be (center, radius)");
    const Doubles c = as_vector(pair[0], 2, "ball center");
    const Circle circle{{c.at(0), c.at(1)}, pair[1].cast<double>()};
    return run<Segment2>(array, threads, [&](auto s, auto o, auto k, auto opt) {
      clip::clip_segments(s, circle, o, k, opt);
    });
  }
  const Doubles ring_points = as_matrix(convex, 2, "convex ring");
  require_finite(ring_points, "convex ring", 1);
  const auto span = as_vec2(ring_points);
  const Ring ring(span.begin(), span.end());
  if (ring.size() < 3) fail(ErrorKind::degenerate, "convex ring needs at least 3 points");
  return run<Segment2>(array, threads, [&](auto s, auto o, auto k, auto opt) {
    clip::clip_segments(s, ring, o, k, opt);
  });
}

}  // namespace

void bind_clip(py::module_& m) {
  m.def(
      "clip_segments",
      [](const ArrayLike& segments, const py::object& box, const py::object& halfspace,
         const py::object& ball, const py::object& convex, int threads) {
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
        return three ? clip3(rows, box, halfspace, ball, convex, threads)
                     : clip2(rows, box, halfspace, ball, convex, threads);
      },
      "segments"_a, py::kw_only(), "box"_a = py::none(), "halfspace"_a = py::none(),
      "ball"_a = py::none(), "convex"_a = py::none(), "threads"_a = 0, R"doc(
Clips every segment to a closed region; returns (clipped, kept).

segments: (N, 4) rows x0 y0 x1 y1 (2D) or (N, 6) rows x0 y0 z0 x1 y1 z1 (3D), or (N, 2, d).
Exactly one region:
  box=(min, max)            an axis-aligned box (Liang-Barsky, exact decisions)
  halfspace=(a, b, c[, d])  a x + b y [+ c z] + d >= 0 (3 numbers in 2D, 4 in 3D)
  ball=(center, radius)     a closed disc / ball
  convex=...                2D: a convex ring (K, 2), counter-clockwise;
                            3D: (M, 4) planes a b c d (inside where >= 0) or a convex Mesh
                            (Cyrus-Beck).
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
          return py::str(io::write_wkt(result));
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
