// OBJ and OFF readers of contain/io/mesh_io.h.
#include <gtest/gtest.h>

#include "contain/io/mesh_io.h"

namespace contain::io {
namespace {

Result<MeshFile> obj(std::string_view text) {
  return parse_mesh(text, MeshFormat::obj, "m.obj");
}
Result<MeshFile> off(std::string_view text) {
  return parse_mesh(text, MeshFormat::off, "m.off");
}

const std::vector<Vec3> kQuad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(ObjReader, FanTriangulatesPolygonalFacesAndCountsThem) {
  auto r = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.vertices, kQuad);
  EXPECT_EQ(r->mesh.triangles, (std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(r->info.faces, 1);
  EXPECT_EQ(r->info.format, MeshFormat::obj);
}

TEST(ObjReader, ReadsEveryVertexReferenceFormAndNegativeIndices) {
  auto r =
      obj("# comment\nmtllib a.mtl\no thing\ng group\ns 1\nusemtl red\n"
          "v 0 0 0 1\nv 1 0 0\nv 1 1 0\nv 0 1 0 0.5\nvt 0 0\nvn 0 0 1\nvp 0.5\n"
          "f 1/1 2/1 3/1\nf 1//1 3//1 4//1\nf 1/1/1 2/1/1 4/1/1\nf -4 -3 -1\nl 1 2\n\n");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.vertices.size(), 4u);
  EXPECT_EQ(r->mesh.triangles,
            (std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {0, 1, 3}}));
}

TEST(ObjReader, AcceptsFacesBeforeTheirVerticesAndCrLfLines) {
  auto r = obj("f 1 2 3\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
}

struct BadMesh {
  const char* text;
  ErrorKind kind;
  std::int64_t line;
};

void expect_errors(MeshFormat format, std::initializer_list<BadMesh> cases) {
  for (const BadMesh& c : cases) {
    auto r = parse_mesh(c.text, format, "bad");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().kind, c.kind) << c.text << "\n" << r.error().what();
    EXPECT_EQ(r.error().line, c.line) << c.text << "\n" << r.error().what();
    EXPECT_EQ(r.error().source, "bad");
  }
}

TEST(ObjReader, RejectsMalformedFilesNamingTheKindAndLine) {
  expect_errors(MeshFormat::obj,
                {
                    {"", ErrorKind::parse, 1},                               // empty
                    {"\n\n", ErrorKind::parse, 1},                           // blank
                    {"v 0 0 0\nv 1 0\n", ErrorKind::parse, 2},               // truncated
                    {"v 0 0 0\nv 1 x 0\n", ErrorKind::parse, 2},             // bad number
                    {"v 0 0 0\nv 1 0 0z\n", ErrorKind::parse, 2},            // glued text
                    {"v 0 0 0\nv 1 nan 0\n", ErrorKind::invalid_value, 2},   // NaN
                    {"v 0 0 0\nv 1 -inf 0\n", ErrorKind::invalid_value, 2},  // Inf
                    {"v 0 0 1e999\n", ErrorKind::invalid_value, 1},          // overflow
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n", ErrorKind::invalid_value, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", ErrorKind::invalid_value, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", ErrorKind::invalid_value, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", ErrorKind::degenerate, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", ErrorKind::parse, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n", ErrorKind::parse, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", ErrorKind::parse, 4},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 99999999999 2 3\n", ErrorKind::invalid_value, 4},
                    {"v 0 0 0\nvertex 1 0 0\n", ErrorKind::parse, 2},  // unknown statement
                    {"v 0 0 0\ncstype bspline\n", ErrorKind::unsupported, 2},
                    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", ErrorKind::degenerate, 0},  // no faces
                });
}

TEST(OffReader, ReadsCountsOnTheHeaderLineCommentsAndFaceColours) {
  auto r = off(
      "OFF 4 1 0 # counts here\n# a comment\n0 0 0\n1 0 0\n\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.vertices, kQuad);
  EXPECT_EQ(r->mesh.triangles, (std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(r->info.faces, 1);
}

TEST(OffReader, PlainAndDecoratedLinesReadAlike) {
  // Plain "x y z" and "3 a b c" lines take the quick reading; CR LF ends, tabs, signs, trailing
  // comments and a face colour take the general one: the same mesh either way.
  auto plain = off("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  auto decorated =
      off("OFF\r\n4 2 0\r\n+0 0 0 # origin\r\n1\t0 -0.0\r\n1 1 +0\r\n0 1 0e0\r\n3 0 1 2 # one\r\n"
          "3\t0 2 3 0.5 0.5 0.5\r\n");
  ASSERT_TRUE(plain.ok()) << plain.error().what();
  ASSERT_TRUE(decorated.ok()) << decorated.error().what();
  EXPECT_EQ(plain->mesh, decorated->mesh);
  EXPECT_EQ(plain->mesh.vertices, kQuad);
  EXPECT_EQ(decorated->info.faces, 2);
}

TEST(OffReader, ReadsCoffAndNoffVertexLines) {
  auto c = off("COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(c.ok()) << c.error().what();
  auto n = off("NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(n.ok()) << n.error().what();
  EXPECT_EQ(c->mesh, n->mesh);
}

TEST(OffReader, RejectsMalformedFilesNamingTheKindAndLine) {
  expect_errors(MeshFormat::off,
                {
                    {"", ErrorKind::parse, 1},              // empty
                    {"OFF\n", ErrorKind::parse, 1},         // no counts
                    {"PLY\n3 1 0\n", ErrorKind::parse, 1},  // wrong type
                    {"4OFF\n3 1 0\n", ErrorKind::unsupported, 1},
                    {"OFF BINARY\n3 1 0\n", ErrorKind::unsupported, 1},
                    {"OFF\n3 x 0\n", ErrorKind::parse, 2},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n", ErrorKind::parse, 4},  // truncated
                    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ErrorKind::parse, 6},  // count
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", ErrorKind::parse, 7},
                    {"OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", ErrorKind::parse, 4},
                    {"OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n", ErrorKind::invalid_value, 4},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", ErrorKind::invalid_value, 6},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", ErrorKind::invalid_value, 6},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ErrorKind::degenerate, 6},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", ErrorKind::parse, 6},
                    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", ErrorKind::parse, 6},
                    {"OFF\n-3 1 0\n", ErrorKind::invalid_value, 2},
                    {"OFF\n3000000000 1 0\n", ErrorKind::unsupported, 2},
                    {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", ErrorKind::degenerate, 0},
                });
}

// The vertex and face blocks are read by a one-pass scanner that hands the lines it cannot take
// to the general reading: decorated lines, whichever of the two takes them, read as plain ones.
TEST(OffReader, OnePassScannerAndGeneralReadingAgreeOnDecoratedLines) {
  const char* plain = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  auto expected = off(plain);
  ASSERT_TRUE(expected.ok()) << expected.error().what();
  for (const char* text : {
           "OFF\r\n4 2 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n3 0 1 2\r\n3 0 2 3\r\n",
           "OFF\n4 2 0\n0\t0\t0\n1 0 0\n1 1 0\n0 1 0\n3\t0 1\t2\n3 0 2 3\n",
           "OFF\n4 2 0\n0 0 0#c\n# whole line\n1 0 0\n1 1 0 # c\n\n\n0 1 0\n3 0 1 2#x\n3 0 2 3 # y",
           "OFF\n4 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 nan\n0 1 0 1\n3 0 1 2 0.5 0.5 0.5\n"
           "3 0 2 3 1 1 1\n",
           "OFF\n4 2 0\n+0 0 0\n1 +0 0\n1 1e0 .0\n-0 1 0\n3 00 01 2\n3 0 2 3",
           "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n\n# the end\n",
           "OFF\n4 2 0\n0 0 0\r\n1\v0\f0 \r\n1 1 0\n0 1 0\n3 0 1 2\r\n3 0 2 3\n",
       }) {
    auto r = off(text);
    ASSERT_TRUE(r.ok()) << text << "\n" << r.error().what();
    EXPECT_EQ(r->mesh.vertices, expected->mesh.vertices) << text;
    EXPECT_EQ(r->mesh.triangles, expected->mesh.triangles) << text;
    EXPECT_EQ(r->info.faces, 2) << text;
  }
  auto quad = off("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 0.5 0.5 0.5\n");
  ASSERT_TRUE(quad.ok()) << quad.error().what();
  EXPECT_EQ(quad->mesh.triangles, expected->mesh.triangles);
  EXPECT_EQ(quad->info.faces, 1);
}

// A line the scanner declines after lines it took is worded by the general reading, with its line.
TEST(OffReader, ErrorsAfterScannedLinesKeepTheirKindAndLine) {
  const std::string head = "OFF\n4 2 0\n0 0 0\n1 0 0\n";
  const std::string v34 = "1 1 0\n0 1 0\n";
  const std::string f1 = "3 0 1 2\n";
  const std::string texts[] = {
      head + "1 nan 0\n0 1 0\n" + f1 + "3 0 2 3\n",
      head + "1 1e400 0\n0 1 0\n" + f1 + "3 0 2 3\n",
      head + "1 1 0x\n0 1 0\n" + f1 + "3 0 2 3\n",
      head + "1,1,0\n0 1 0\n" + f1 + "3 0 2 3\n",
      head + v34 + f1 + "3 0 2 4\n",
      head + v34 + f1 + "3 0 -2 3\n",
      head + v34 + f1 + "3 0 2 99999999999\n",
      head + v34 + f1 + "4 0 2 3\n",
      head + v34 + f1 + "2 0 2\n",
      head + v34 + f1 + "3 0 2 3 red\n",
      head + v34 + f1 + "3 0 2 3\nfoo\n",
      head + v34 + f1 + "\n\n",
      "OFF\n5 2 0\n0 0 0\n1 0 0\n" + v34 + f1 + "3 0 2 3\n",
  };
  const BadMesh expected[] = {
      {nullptr, ErrorKind::invalid_value, 5}, {nullptr, ErrorKind::invalid_value, 5},
      {nullptr, ErrorKind::parse, 5},         {nullptr, ErrorKind::parse, 5},
      {nullptr, ErrorKind::invalid_value, 8}, {nullptr, ErrorKind::invalid_value, 8},
      {nullptr, ErrorKind::invalid_value, 8}, {nullptr, ErrorKind::parse, 8},
      {nullptr, ErrorKind::degenerate, 8},    {nullptr, ErrorKind::parse, 8},
      {nullptr, ErrorKind::parse, 9},         {nullptr, ErrorKind::parse, 9},
      {nullptr, ErrorKind::parse, 8},
  };
  for (std::size_t i = 0; i < std::size(texts); ++i) {
    auto r = off(texts[i]);
    ASSERT_FALSE(r.ok()) << texts[i];
    EXPECT_EQ(r.error().kind, expected[i].kind) << texts[i] << "\n" << r.error().what();
    EXPECT_EQ(r.error().line, expected[i].line) << texts[i] << "\n" << r.error().what();
  }
}

TEST(OffReader, AHugeCountInTheHeaderIsATruncationNotAnAllocation) {
  auto r = off("OFF\n2000000000 2000000000 0\n0 0 0\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::parse);
}

}  // namespace
}  // namespace contain::io
