// The extension module contain._contain; the package contain re-exports it.

#include <pybind11/pybind11.h>

#include "arrays.h"
#include "bindings.h"
#include "errors.h"
#include "shapes.h"

PYBIND11_MODULE(_contain, m) {
  namespace py = pybind11;
  using namespace contain::python;
  m.doc() =
      "Exact point containment, collision and clipping in 2D and 3D (the contain C++ library).";
  register_errors(m);
  make_location_enum(m);
  bind_shapes(m);
  bind_io(m);
  bind_inside(m);
  bind_collide(m);
  bind_ccd(m);
  bind_clip(m);
  bind_bound(m);
  bind_convex(m);  // before the users of ConvexPolyhedron's Python type in their signatures
  bind_csg(m);
  bind_clip_regions(m);
  bind_mesh_report(m);
  bind_primitives(m);
  bind_winding(m);
  bind_tile(m);
  bind_layer(m);
  bind_distance(m);
  bind_mesh_boolean(m);
  bind_slice(m);
  bind_points(m);
  m.def("_reads_in_place", &reads_in_place, py::arg("array"),
        "True when the batch calls read `array` without a copy (C-contiguous aligned float64).");
#ifdef CONTAIN_VERSION
  m.attr("__version__") = CONTAIN_VERSION;
#endif
}
