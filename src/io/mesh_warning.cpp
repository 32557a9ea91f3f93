#include "contain/io/mesh_warning.h"

#include <charconv>
#include <string>
#include <string_view>
#include <vector>

namespace contain::io {
namespace {

// "1 edge", "2 edges"; `many` where the plural is not the word and an s.
std::string plural(std::size_t n, const std::string& word, const std::string& many = "") {
  return std::to_string(n) + " " + (n == 1 ? word : many.empty() ? word + "s" : many);
}

std::string_view reading_words(OpenMeshReading reading) {
  switch (reading) {
    case OpenMeshReading::surface_contact:
      return "read as a surface, which meets the other shape only where they share a point";
    case OpenMeshReading::surface_contact_in_scene:
      return "read as a surface, which meets another shape only where they share a point";
    case OpenMeshReading::surface_distance:
      return "read as a surface, whose distance is to its triangles only";
    case OpenMeshReading::winding_number_sign:
      return "signs come from the generalized winding number (inside where >= 0.5)";
  }
  return "";
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? ", " : "") + parts[i];
  return out;
}

}  // namespace

std::string mesh_warning(inside::MeshRegime regime, const MeshReport& report) {
  // Facts that leave the exact regime exact (and are said in either regime).
  std::vector<std::string> notes;
  if (!report.pinch_vertices.empty()) {
    notes.push_back(plural(report.pinch_vertices.size(), "pinch vertex", "pinch vertices") +
                    " (not 2-manifold there; first: " +
                    std::to_string(report.pinch_vertices.front() + 1) + ", 1-based)");
  }
  if (report.inconsistent_edges > 0) {
    notes.push_back("inconsistent orientation (" + plural(report.inconsistent_edges, "edge") +
                    " used in the same direction)");
  }
  if (report.degenerate_triangles > 0) {
    notes.push_back(plural(report.degenerate_triangles, "degenerate triangle"));
  }
  if (regime == inside::MeshRegime::closed_exact) {
    // Two copies of a triangle with opposite orientations still close every edge: parity stays
    // exact (the pair bounds no volume), but the user should hear of it.
    if (report.duplicated_triangles > 0) {
      notes.push_back(plural(report.duplicated_triangles, "duplicated triangle"));
    }
    // A whole mesh turned inside out is an empty solid: every point is 'out', which a user who
    // meant the solid it wraps must hear of.
    const bool inverted = report.inconsistent_edges == 0 && report.signed_volume < 0.0;
    if (notes.empty() && !inverted) return "";
    const std::string inside_out =
        "mesh is turned inside out (negative volume): as a solid (where its winding number is "
        "positive) a shell turned inside out subtracts and alone holds no point, so the points it "
        "wraps are 'out'; reverse its triangles for the solid it bounds";
    if (notes.empty()) return inside_out;
    // Without a consistent orientation there is no winding number: the answers are ray parity.
    const std::string exact = report.inconsistent_edges > 0
                                  ? "; every edge has exactly two triangles, so the answers "
                                    "(closed-exact ray parity) are still exact"
                                  : "; the mesh is closed, so the answers (the solid of its "
                                    "winding number) are still exact";
    return "mesh has " + joined(notes) + exact + (inverted ? "; " + inside_out : "");
  }
  std::vector<std::string> why;
  if (report.triangles == 0) why.push_back("no triangles");
  if (report.border_edges > 0) why.push_back(plural(report.border_edges, "border edge"));
  if (report.nonmanifold_edges > 0) {
    why.push_back(plural(report.nonmanifold_edges, "edge") + " of three or more triangles");
  }
  if (report.duplicated_triangles > 0) {
    why.push_back(plural(report.duplicated_triangles, "duplicated triangle"));
  }
  why.insert(why.end(), notes.begin(), notes.end());
  return "mesh is not closed (" + joined(why) +
         "): answers come from the generalized winding number (winding-number regime: inside "
         "where it is >= 0.5, approximate near the surface); points exactly on the surface are "
         "still 'on'";
}

std::string open_mesh_warning(std::string_view name, const MeshReport& report,
                              OpenMeshReading reading) {
  return std::string(name) + ": not closed (" + std::to_string(report.border_edges) +
         " border edges, " + std::to_string(report.nonmanifold_edges) +
         " non-manifold edges): " + std::string(reading_words(reading));
}

std::string open_mesh_warning(std::string_view name, OpenMeshReading reading) {
  return std::string(name) + ": not closed: " + std::string(reading_words(reading));
}

namespace {

std::string shortest(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return {text, end};
}

std::string point_words(Vec3 p) {
  return "(" + shortest(p.x) + " " + shortest(p.y) + " " + shortest(p.z) + ")";
}

}  // namespace

std::string open_solid_message(std::string_view name, const UnmatchedEdge& edge) {
  return std::string(name) + ": not closed: the directed edge " + point_words(edge.from) + " -> " +
         point_words(edge.to) + " of triangle " + std::to_string(edge.triangle) +
         " (counted from 0 in file order, polygons split into fans) occurs " +
         std::to_string(edge.count) + (edge.count == 1 ? " time" : " times") + ", its reverse " +
         std::to_string(edge.reverse) + (edge.reverse == 1 ? " time" : " times") +
         "; a solid's mesh has every directed edge as often as its reverse";
}

}  // namespace contain::io
