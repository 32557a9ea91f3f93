#include "contain/inside/solid_rule.h"

#include "contain/shapes/mesh_closure.h"

namespace contain::inside {

SolidRule solid_rule(const Mesh& mesh, const MeshReport& report) {
  // Closed and consistently oriented by index implies every directed edge matched by position;
  // the search by position is needed only when the report cannot tell.
  const bool matched = (report.closed() && report.consistently_oriented()) ||
                       (!mesh.triangles.empty() && !unmatched_edge(mesh).has_value());
  if (matched) return SolidRule::winding;
  return report.closed() ? SolidRule::parity : SolidRule::none;
}

}  // namespace contain::inside
