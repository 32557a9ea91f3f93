// Exact tests on batches of primitives: contain.tri_tri (2D and 3D), segment_triangle,
// segment_segment, pair_search (the broad phase), orient2d, orient3d; tri_tri_2d and
// segments_intersect, their old names, deprecated.

#include <pybind11/stl.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/pair_search.h"
#include "contain/collide/tri_tri.h"
#include "contain/collide/tri_tri_2d.h"
#include "contain/core/parallel.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "errors.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// Items are rows of doubles laid out exactly as the library's aggregates of Vec2 / Vec3.
template <class T>
T item_as(const Items& items, std::size_t i) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value;
  std::memcpy(static_cast<void*>(&value), items.item(items.single ? 0 : i), sizeof(T));
  return value;
}

static_assert(sizeof(Triangle3) == 9 * sizeof(double) && sizeof(Triangle2) == 6 * sizeof(double));
static_assert(sizeof(Segment3) == 6 * sizeof(double) && sizeof(Segment2) == 4 * sizeof(double));

// Runs `test(i) -> bool` for every pair without the GIL on `threads` threads.
template <class Test>
py::object pairs(const Items& a, const Items& b, const char* what, int threads, Test&& test) {
  const std::size_t n = paired_count(a, b, what);
  std::vector<std::uint8_t> out(n);
  {
    py::gil_scoped_release release;
    parallel_for(n, BatchOptions{.threads = threads}, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        out[i] = test(i) ? 1 : 0;
    });
  }
  return to_bools(std::move(out), a.single && b.single);
}

// Triangles in the plane when the array's last axis holds 2D points or flat 2D triangles
// ((N, 3, 2), (N, 6), (3, 2)); anything else is read as triangles in space, whose errors name
// the 3D shapes.
bool planar_items(const py::handle& object) {
  const py::array array = py::array::ensure(object);
  if (!array || array.ndim() < 1) return false;
  const py::ssize_t last = array.shape(array.ndim() - 1);
  return last == 2 || last == 6;
}

py::object tri_tri_3d(const ArrayLike& a, const ArrayLike& b, int threads) {
  const Items ta = as_items(a.object, 3, 3, "a"), tb = as_items(b.object, 3, 3, "b");
  return pairs(ta, tb, "tri_tri", threads, [&](std::size_t i) {
    return collide::tri_tri(item_as<Triangle3>(ta, i), item_as<Triangle3>(tb, i));
  });
}

py::object tri_tri_2d(const ArrayLike& a, const ArrayLike& b, int threads) {
  const Items ta = as_items(a.object, 3, 2, "a"), tb = as_items(b.object, 3, 2, "b");
  return pairs(ta, tb, "tri_tri", threads, [&](std::size_t i) {
    return collide::tri_tri(item_as<Triangle2>(ta, i), item_as<Triangle2>(tb, i));
  });
}

py::object segment_segment(const ArrayLike& a, const ArrayLike& b, int threads) {
  const Items sa = as_items(a.object, 2, 2, "a"), sb = as_items(b.object, 2, 2, "b");
  return pairs(sa, sb, "segment_segment", threads, [&](std::size_t i) {
    return collide::segment_segment(item_as<Segment2>(sa, i), item_as<Segment2>(sb, i));
  });
}

constexpr const char* kPairsDoc = R"doc(

Pairs item i of `a` with item i of `b`; a single item pairs with every item of the other.
Returns a bool array (N,), or a bool when both are single items. Every decision is an exact
predicate sign on the given doubles (NaN/Inf raise ContainError). Runs on `threads` threads
(0: every core) without the GIL.
)doc";

std::string doc(const char* head) {
  return std::string(head) + kPairsDoc;
}

// Boxes as Box3: (N, 2, 3) / (N, 6) rows min then max, or a pair (lo (N, 3), hi (N, 3)); 2D boxes
// ((N, 2, 2), (N, 4), or a pair of (N, 2)) lie in the plane z = 0.
std::vector<Box3> to_boxes(const py::handle& object) {
  if (py::isinstance<py::tuple>(object) && py::len(object) == 2) {
    const auto pair = py::reinterpret_borrow<py::tuple>(object);
    const py::array lo_array = py::array::ensure(pair[0]);
    if (!lo_array) PyErr_Clear();
    const py::ssize_t dim = lo_array && lo_array.ndim() == 2 ? lo_array.shape(1) : 3;
    const Doubles lo = as_matrix(pair[0], dim == 2 ? 2 : 3, "boxes min");
    const Doubles hi = as_matrix(pair[1], dim == 2 ? 2 : 3, "boxes max");
    if (lo.shape(0) != hi.shape(0)) throw py::value_error("boxes: min and max differ in length");
    require_finite(lo, "boxes min", 0);
    require_finite(hi, "boxes max", 0);
    std::vector<Box3> boxes(static_cast<std::size_t>(lo.shape(0)));
    const std::size_t d = static_cast<std::size_t>(lo.shape(1));
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double* l = lo.data() + d * i;
      const double* h = hi.data() + d * i;
      boxes[i] = {{l[0], l[1], d == 3 ? l[2] : 0.0}, {h[0], h[1], d == 3 ? h[2] : 0.0}};
    }
    return boxes;
  }
  const py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error("boxes must be an (N, 2, 3) or (N, 6) array, or a pair (min, max)");
  }
  const bool two_d =
      (array.ndim() == 3 && array.shape(2) == 2) || (array.ndim() == 2 && array.shape(1) == 4);
  const Items items = as_items(array, 2, two_d ? 2 : 3, "boxes");
  std::vector<Box3> boxes(items.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const double* r = items.item(i);
    boxes[i] = two_d ? Box3{{r[0], r[1], 0.0}, {r[2], r[3], 0.0}}
                     : Box3{{r[0], r[1], r[2]}, {r[3], r[4], r[5]}};
  }
  return boxes;
}

template <class Point, class Sign4>
py::object orientations(const std::vector<Items>& points, int threads, Sign4&& sign) {
  std::size_t n = 0;
  bool single = true;
  for (const Items& p : points) {
    single = single && p.single;
    if (!p.single) {
      if (n != 0 && p.size() != n) {
        throw py::value_error("the point batches differ in length (" + std::to_string(n) + " and " +
                              std::to_string(p.size()) + ")");
      }
      n = p.size();
    }
  }
  if (single) n = 1;
  std::vector<std::int8_t> out(n);
  {
    py::gil_scoped_release release;
    parallel_for(n, BatchOptions{.threads = threads}, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        out[i] = static_cast<std::int8_t>(sign(i));
    });
  }
  return to_int8s(std::move(out), single);
}

}  // namespace

void bind_primitives(py::module_& m) {
  static const std::string tri_doc = doc(R"doc(
Do closed triangles share a point? C++ collide::tri_tri. In space a, b: (N, 3, 3) (three
vertices x y z each), (N, 9) or one (3, 3) triangle: crossing, touching at a vertex or along an
edge and coplanar overlap all count; degenerate triangles are the segment or point they span
(Guigue-Devillers with exact orient3d, docs/collision.md). In the plane (chosen by a's shape)
a, b: (N, 3, 2), (N, 6) or one (3, 2) triangle, either winding: touching counts, and so does one
inside the other (exercise 22.4-5).)doc");
  m.def(
      "tri_tri",
      [](const ArrayLike& a, const ArrayLike& b, int threads) {
        return planar_items(a.object) ? tri_tri_2d(a, b, threads) : tri_tri_3d(a, b, threads);
      },
      "a"_a, "b"_a, py::kw_only(), "threads"_a = 0, tri_doc.c_str());
  m.def(
      "tri_tri_2d",
      [](const ArrayLike& a, const ArrayLike& b, int threads) {
        warn_deprecated("contain.tri_tri_2d", "contain.tri_tri");
        return tri_tri_2d(a, b, threads);
      },
      "a"_a, "b"_a, py::kw_only(), "threads"_a = 0,
      "Deprecated: contain.tri_tri(a, b), which takes 2D triangles by their shape (a "
      "DeprecationWarning); the same answer.");

  static const std::string seg_tri_doc = doc(R"doc(
Does the closed segment meet the closed triangle? segments: (N, 2, 3), (N, 6) or one (2, 3);
triangles: (N, 3, 3), (N, 9) or one (3, 3). The section's edge-face test made exact.)doc");
  m.def(
      "segment_triangle",
      [](const ArrayLike& segments, const ArrayLike& triangles, int threads) {
        const Items s = as_items(segments.object, 2, 3, "segments");
        const Items t = as_items(triangles.object, 3, 3, "triangles");
        return pairs(s, t, "segment_triangle", threads, [&](std::size_t i) {
          return collide::segment_triangle(item_as<Segment3>(s, i), item_as<Triangle3>(t, i));
        });
      },
      "segments"_a, "triangles"_a, py::kw_only(), "threads"_a = 0, seg_tri_doc.c_str());

  static const std::string seg_seg_doc = doc(R"doc(
Do closed segments in the plane share a point? C++ collide::segment_segment. a, b: (N, 2, 2),
(N, 4) or one (2, 2); collinear overlap and zero-length segments included.)doc");
  m.def("segment_segment", &segment_segment, "a"_a, "b"_a, py::kw_only(), "threads"_a = 0,
        seg_seg_doc.c_str());
  m.def(
      "segments_intersect",
      [](const ArrayLike& a, const ArrayLike& b, int threads) {
        warn_deprecated("contain.segments_intersect", "contain.segment_segment");
        return segment_segment(a, b, threads);
      },
      "a"_a, "b"_a, py::kw_only(), "threads"_a = 0,
      "Deprecated: contain.segment_segment(a, b), the C++ name (a DeprecationWarning); the same "
      "answer.");

  m.def(
      "pair_search",
      [](const ArrayLike& boxes) {
        const std::vector<Box3> b = to_boxes(boxes.object);
        std::vector<std::pair<std::int32_t, std::int32_t>> found;
        {
          py::gil_scoped_release release;
          found = collide::pair_search(b);
        }
        std::vector<std::int32_t> flat;
        flat.reserve(2 * found.size());
        for (const auto& [i, j] : found) {
          flat.push_back(i);
          flat.push_back(j);
        }
        auto* owned = new std::vector<std::int32_t>(std::move(flat));
        py::capsule base(owned, [](void* p) { delete static_cast<std::vector<std::int32_t>*>(p); });
        return py::array_t<std::int32_t>({static_cast<py::ssize_t>(found.size()), py::ssize_t{2}},
                                         owned->data(), base);
      },
      "boxes"_a, R"doc(
The broad phase of a scene: every pair (i, j), i < j, of closed axis-aligned boxes that share a
point (touching counts), as an (K, 2) int32 array sorted lexicographically.

boxes: (N, 2, 3) or (N, 6) rows (min x y z, max x y z), or a pair (min (N, 3), max (N, 3)); 2D
boxes ((N, 2, 2), (N, 4), a pair of (N, 2)) work the same. Empty boxes (min > max) pair with
nothing. Exact (comparisons only). Sweep and prune along the axis of widest spread,
O(n log n + pairs overlapping on that axis).

Example:
    >>> lo = np.array([[0, 0, 0], [1, 0, 0], [5, 5, 5]])
    >>> contain.pair_search((lo, lo + 1))
    array([[0, 1]], dtype=int32)
)doc");

  m.def(
      "orient2d",
      [](const ArrayLike& a, const ArrayLike& b, const ArrayLike& c, int threads) {
        const std::vector<Items> p = {as_items(a.object, 1, 2, "a"), as_items(b.object, 1, 2, "b"),
                                      as_items(c.object, 1, 2, "c")};
        return orientations<Vec2>(p, threads, [&](std::size_t i) {
          return static_cast<int>(predicates::orient2d(
              item_as<Vec2>(p[0], i), item_as<Vec2>(p[1], i), item_as<Vec2>(p[2], i)));
        });
      },
      "a"_a, "b"_a, "c"_a, py::kw_only(), "threads"_a = 0, R"doc(
The exact sign of det[b - a, c - a] for points of shape (N, 2) or one (2,): 1 when a, b, c
turn counter-clockwise, 0 when collinear, -1 clockwise. An int8 array (N,), or an int for
single points. Exact on every finite double (filter, expansions, big numbers).
)doc");
  m.def(
      "orient3d",
      [](const ArrayLike& a, const ArrayLike& b, const ArrayLike& c, const ArrayLike& d,
         int threads) {
        const std::vector<Items> p = {as_items(a.object, 1, 3, "a"), as_items(b.object, 1, 3, "b"),
                                      as_items(c.object, 1, 3, "c"), as_items(d.object, 1, 3, "d")};
        return orientations<Vec3>(p, threads, [&](std::size_t i) {
          return static_cast<int>(
              predicates::orient3d(item_as<Vec3>(p[0], i), item_as<Vec3>(p[1], i),
                                   item_as<Vec3>(p[2], i), item_as<Vec3>(p[3], i)));
        });
      },
      "a"_a, "b"_a, "c"_a, "d"_a, py::kw_only(), "threads"_a = 0, R"doc(
The exact sign of ((b - a) x (c - a)) . (d - a) for points of shape (N, 3) or one (3,): 1 when d
lies on the side the normal of a, b, c (counter-clockwise) points to, 0 when coplanar, -1 on the
other side (CGAL's convention; the opposite of Shewchuk's orient3d). int8 array or int.
)doc");
}

}  // namespace contain::python
