#pragma once
/// \file
/// Solids defined by a function, f(p) >= 0 ("Algorithms of Informatics" vol. 2, § 22.4,
/// equation 22.1), as data; inside::point_in_implicit locates points in them.

#include <functional>

#include "contain/values/vec.h"

namespace contain::shapes {

/// A user-supplied implicit function: the solid is { p : f(p) >= 0 }.
/// Batch callers (`inside::CsgSolid::locate` on many points) call it from several threads at
/// once, so it must be safe to call concurrently (a pure function is; see io::read_csg_json for
/// the muparser adaptor, which keeps one parser per concurrent caller).
using ImplicitFunction = std::function<double(Vec3)>;

}  // namespace contain::shapes

// Users and every layer above spell this name contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::ImplicitFunction;
}  // namespace contain
