#pragma once
/// \file
/// Conversions shared by the bindings: option strings, regions from WKT or rings, transforms,
/// the `Location` enum object and boolean answers under a boundary policy.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "contain/core/location.h"
#include "contain/shapes/polygon.h"
#include "contain/values/transform.h"

namespace contain::python {

namespace py = pybind11;

/// "even_odd", "nonzero", "positive", "negative" (also "evenodd"); ValueError otherwise.
[[nodiscard]] Fill parse_fill(const std::string& fill);
[[nodiscard]] const char* fill_name(Fill fill);

/// A region: a `contain.Region`, a WKT string (POLYGON or MULTIPOLYGON), or a sequence of rings
/// (each an (K, 2) array of x, y; all rings together are one polygon's closed paths).
[[nodiscard]] MultiPolygon to_region(const py::handle& object, const char* name);

/// A transform: None (identity), 12 numbers in the contract's row order r00 r01 r02 t0 r10 ...,
/// a (3, 4) matrix [R | t] or a (4, 4) matrix whose last row is 0 0 0 1.
[[nodiscard]] Transform to_transform(const py::handle& object, const char* name);

/// The `contain.Location` IntEnum member of `location` (created by `make_location_enum`).
[[nodiscard]] py::object location_object(Location location);
/// Creates `contain.Location` (enum.IntEnum: outside = -1, boundary = 0, inside = 1).
void make_location_enum(py::module_& module);

/// Booleans from locations under `boundary`: "inside" (boundary counts as inside), "outside",
/// or "raise" (ContainError naming the first boundary point). ValueError for another word.
[[nodiscard]] py::array_t<bool> to_booleans(const std::vector<Location>& locations,
                                            const std::string& boundary);

/// Checks the policy word before any work is done.
void check_boundary_policy(const std::string& boundary);

}  // namespace contain::python
