#pragma once
// contain index build (a saved index) and contain inside --index (answers from one).

#include <string>

#include "many.h"

namespace contain::cli {

/// contain inside --index FILE [--mesh MESH]: the saved index answers; with MESH, it must have
/// been built from MESH's triangles (exit 3 naming both files otherwise).
int run_inside_index(const PointQuery& query, const std::string& index, const std::string& mesh);

}  // namespace contain::cli
