#pragma once
// The exact check of a written mesh (rule solid-output in docs/robustness.md). Private to clip.

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::clip::solid {

/// Ok when, on the mesh's doubles exactly: every directed edge occurs once and its reverse
/// once, no triangle has zero area, and no two triangles meet other than at corners at the same
/// positions or a shared edge. Otherwise `ErrorKind::degenerate` naming what failed.
[[nodiscard]] Status check_written(const Mesh& mesh);

}  // namespace contain::clip::solid
