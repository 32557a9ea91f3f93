#pragma once
// Private to contain::io: implicit functions from muparser expressions in x, y, z.

#include <string>

#include "contain/core/result.h"
#include "contain/shapes/implicit_function.h"

namespace contain::io::detail {

/// Compiles `expression` (muparser syntax: x, y, z, `^` for powers, the usual functions). On a
/// syntax error, ErrorKind::parse with muparser's message and position. The function is safe to
/// call concurrently: each concurrent call borrows its own parser from a pool.
[[nodiscard]] Result<ImplicitFunction> compile_expression(const std::string& expression);

}  // namespace contain::io::detail
