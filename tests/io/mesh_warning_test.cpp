#include "contain/io/mesh_warning.h"

#include <gtest/gtest.h>

#include <string>

namespace contain::io {
namespace {

using inside::MeshRegime;

MeshReport closed_report() {
  MeshReport r;
  r.triangles = 12;
  r.edges = 18;
  return r;
}

TEST(MeshWarning, APlainClosedMeshNeedsNoWords) {
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, closed_report()), "");
}

TEST(MeshWarning, OpenMeshNamesTheWindingNumberRegimeAndEveryReason) {
  MeshReport r = closed_report();
  r.border_edges = 4;
  EXPECT_EQ(mesh_warning(MeshRegime::winding_number, r),
            "mesh is not closed (4 border edges): answers come from the generalized winding number "
            "(winding-number regime: inside where it is >= 0.5, approximate near the surface); "
            "points exactly on the surface are still 'on'");
  r.border_edges = 1;
  r.nonmanifold_edges = 2;
  r.duplicated_triangles = 1;
  r.pinch_vertices = {6};
  r.inconsistent_edges = 1;
  r.degenerate_triangles = 3;
  const std::string words = mesh_warning(MeshRegime::winding_number, r);
  EXPECT_EQ(words.substr(0, words.find("):")),
            "mesh is not closed (1 border edge, 2 edges of three or more triangles, 1 duplicated "
            "triangle, 1 pinch vertex (not 2-manifold there; first: 7, 1-based), inconsistent "
            "orientation (1 edge used in the same direction), 3 degenerate triangles");
}

TEST(MeshWarning, PinchVerticesArePluralNotVertexs) {
  MeshReport r = closed_report();
  r.pinch_vertices = {3, 8};
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r).substr(0, 74),
            "mesh has 2 pinch vertices (not 2-manifold there; first: 4, 1-based); the m");
}

TEST(MeshWarning, MeshWithoutTrianglesSaysSo) {
  EXPECT_EQ(mesh_warning(MeshRegime::winding_number, MeshReport{}).substr(0, 33),
            "mesh is not closed (no triangles)");
}

TEST(MeshWarning, ClosedMeshWithPinchOrDuplicatesSaysTheAnswersStayExact) {
  MeshReport r = closed_report();
  r.pinch_vertices = {253};
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r),
            "mesh has 1 pinch vertex (not 2-manifold there; first: 254, 1-based); the mesh is "
            "closed, so the answers (the solid of its winding number) are still exact");
  r.pinch_vertices.clear();
  r.duplicated_triangles = 1;
  r.degenerate_triangles = 2;
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r),
            "mesh has 2 degenerate triangles, 1 duplicated triangle; the mesh is closed, so the "
            "answers (the solid of its winding number) are still exact");
  r.duplicated_triangles = 0;
  r.degenerate_triangles = 0;
  r.inconsistent_edges = 2;
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r),
            "mesh has inconsistent orientation (2 edges used in the same direction); every edge "
            "has exactly two triangles, so the answers (closed-exact ray parity) are still exact");
}

TEST(MeshWarning, AMeshTurnedInsideOutSaysItsPointsAreOut) {
  MeshReport r = closed_report();
  r.signed_volume = -1.0;
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r).substr(0, 62),
            "mesh is turned inside out (negative volume): as a solid (where");
  EXPECT_NE(mesh_warning(MeshRegime::closed_exact, r).find("the points it wraps are 'out'"),
            std::string::npos);
  r.signed_volume = 1.0;
  EXPECT_EQ(mesh_warning(MeshRegime::closed_exact, r), "");
}

TEST(MeshWarning, WordsTheReportOfARealOpenMesh) {
  Mesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}};  // the face 1 2 3 is missing
  const MeshReport report = validate_mesh(tetra);
  EXPECT_NE(mesh_warning(MeshRegime::winding_number, report).find("(3 border edges)"),
            std::string::npos);
}

TEST(OpenMeshWarning, NamesTheMeshItsCountsAndHowEachQueryReadsIt) {
  MeshReport r = closed_report();
  r.border_edges = 4;
  r.nonmanifold_edges = 1;
  EXPECT_EQ(open_mesh_warning("a.obj", r, OpenMeshReading::surface_contact),
            "a.obj: not closed (4 border edges, 1 non-manifold edges): read as a surface, which "
            "meets the other shape only where they share a point");
  EXPECT_EQ(open_mesh_warning("b.off", r, OpenMeshReading::surface_distance),
            "b.off: not closed (4 border edges, 1 non-manifold edges): read as a surface, whose "
            "distance is to its triangles only");
  EXPECT_EQ(open_mesh_warning("c.stl", r, OpenMeshReading::winding_number_sign),
            "c.stl: not closed (4 border edges, 1 non-manifold edges): signs come from the "
            "generalized winding number (inside where >= 0.5)");
}

TEST(OpenMeshWarning, WithoutAReportSaysOnlyThatTheMeshIsOpen) {
  EXPECT_EQ(open_mesh_warning("m.obj (object 3)", OpenMeshReading::surface_contact_in_scene),
            "m.obj (object 3): not closed: read as a surface, which meets another shape only where "
            "they share a point");
}

TEST(MeshWarning, OpenSolidNamesTheFileTheEdgeItsTriangleAndTheCounts) {
  const UnmatchedEdge edge{
      .from = {0, 0.1, -2}, .to = {1e300, 0, 0}, .triangle = 7, .count = 1, .reverse = 0};
  EXPECT_EQ(open_solid_message("part.stl", edge),
            "part.stl: not closed: the directed edge (0 0.1 -2) -> (1e+300 0 0) of triangle 7 "
            "(counted from 0 in file order, polygons split into fans) occurs 1 time, its reverse 0 "
            "times; a solid's mesh has every directed edge as often as its reverse");
}

}  // namespace
}  // namespace contain::io
