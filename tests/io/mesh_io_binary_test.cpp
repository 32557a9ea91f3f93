// STL and PLY readers of contain/io/mesh_io.h.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstring>

#include "contain/io/mesh_io.h"

namespace contain::io {
namespace {

Result<MeshFile> stl(std::string_view bytes) {
  return parse_mesh(bytes, MeshFormat::stl_binary, "m.stl");
}
Result<MeshFile> ply(std::string_view bytes) {
  return parse_mesh(bytes, MeshFormat::ply_binary_little_endian, "m.ply");
}

const Mesh kTetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                        {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};

// The corner positions of every triangle, in order: what STL keeps of a mesh.
std::vector<std::array<Vec3, 3>> corners(const Mesh& m) {
  std::vector<std::array<Vec3, 3>> out;
  for (const TriangleIndices& t : m.triangles) {
    out.push_back({m.vertices[static_cast<std::size_t>(t[0])],
                   m.vertices[static_cast<std::size_t>(t[1])],
                   m.vertices[static_cast<std::size_t>(t[2])]});
  }
  return out;
}

const char* kAsciiStl =
    "solid tet\n"
    " facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 1 0\n   vertex 1 0 0\n"
    "  endloop\n endfacet\n"
    " facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 0 1\n"
    "  endloop\n endfacet\n"
    " facet normal -1 0 0\n  outer loop\n   vertex -0 0 0\n   vertex 0 0 1\n   vertex 0 1 0\n"
    "  endloop\n endfacet\n"
    " facet normal 1 1 1\n  outer loop\n   vertex 1 0 0\n   vertex 0 1 0\n   vertex 0 0 1\n"
    "  endloop\n endfacet\n"
    "endsolid tet\n";

TEST(StlReader, WeldsEqualCornersOfAsciiStlIntoAnIndexedMesh) {
  auto r = stl(kAsciiStl);
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.vertices.size(), 4u);  // -0 welded with +0
  EXPECT_EQ(corners(r->mesh), corners(kTetrahedron));
  EXPECT_EQ(r->info.format, MeshFormat::stl_ascii);
  EXPECT_EQ(r->info.faces, 4);
  EXPECT_EQ(r->info.welded_vertices, 8);
}

TEST(StlReader, ReadsBinaryStlEvenWhenItsHeaderBeginsWithSolid) {
  std::string bytes = format_mesh(kTetrahedron, MeshFormat::stl_binary);
  std::memcpy(bytes.data(), "solid but binary", 16);
  auto r = stl(bytes);
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->info.format, MeshFormat::stl_binary);
  EXPECT_EQ(r->mesh.vertices.size(), 4u);
  EXPECT_EQ(corners(r->mesh), corners(kTetrahedron));
}

TEST(StlReader, RejectsATruncatedBinaryFileWithTheByteOffset) {
  const std::string bytes = format_mesh(kTetrahedron, MeshFormat::stl_binary);
  auto r = stl(bytes.substr(0, bytes.size() - 7));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::parse);
  EXPECT_NE(r.error().message.find("byte offset 80"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("truncated"), std::string::npos) << r.error().message;
  auto tiny = stl(bytes.substr(0, 40));
  ASSERT_FALSE(tiny.ok());
  EXPECT_EQ(tiny.error().kind, ErrorKind::parse);
}

TEST(StlReader, ATruncatedBinaryFileWhoseHeaderSaysSolidIsStillReportedAsBinary) {
  std::string bytes = format_mesh(kTetrahedron, MeshFormat::stl_binary);
  std::memcpy(bytes.data(), "solid but binary", 16);
  auto r = stl(bytes.substr(0, bytes.size() - 1));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("binary STL"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("truncated"), std::string::npos) << r.error().message;
}

TEST(StlReader, RejectsNaNInABinaryFileWithTheByteOffset) {
  std::string bytes = format_mesh(kTetrahedron, MeshFormat::stl_binary);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes.data() + 84 + 50 + 12 + 4, &nan, 4);  // triangle 1, first vertex, y
  auto r = stl(bytes);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(r.error().message.find("byte offset 146"), std::string::npos) << r.error().message;
}

TEST(StlReader, RejectsMalformedAsciiStlNamingTheLine) {
  struct Case {
    std::string text;
    ErrorKind kind;
    std::int64_t line;
  };
  const std::string good = kAsciiStl;
  const Case cases[] = {
      {"", ErrorKind::parse, 0},
      {good.substr(0, 200), ErrorKind::parse, 0},  // truncated: checked below for the kind only
      {"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 zero 0\n", ErrorKind::parse,
       5},
      {"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\n",
       ErrorKind::invalid_value, 5},
      {"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n"
       "endsolid\n",
       ErrorKind::degenerate, 6},
      {"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endloop\nendfacet\nendsolid x\ngarbage\n",
       ErrorKind::parse, 10},
      {"solid x\nendsolid x\n", ErrorKind::degenerate, 0},
  };
  for (const Case& c : cases) {
    auto r = stl(c.text);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().kind, c.kind) << c.text << "\n" << r.error().what();
    if (c.line > 0) {
      EXPECT_EQ(r.error().line, c.line) << r.error().what();
    }
  }
}

// A binary big-endian PLY written by hand: float coordinates, an extra property and element,
// uint8 list lengths and uint32 indices.
std::string big_endian_ply() {
  std::string out =
      "ply\nformat binary_big_endian 1.0\ncomment hand made\nelement vertex 4\n"
      "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "element face 4\nproperty list uchar uint vertex_indices\nproperty short flags\n"
      "element edge 1\nproperty int a\nproperty int b\nend_header\n";
  auto put = [&](std::uint64_t v, int n) {
    for (int i = n - 1; i >= 0; --i)
      out += static_cast<char>((v >> (8 * i)) & 0xFF);
  };
  for (const Vec3& v : kTetrahedron.vertices) {
    for (double c : {v.x, v.y, v.z})
      put(std::bit_cast<std::uint32_t>(static_cast<float>(c)), 4);
    put(200, 1);
  }
  for (const TriangleIndices& t : kTetrahedron.triangles) {
    put(3, 1);
    for (std::int32_t i : t)
      put(static_cast<std::uint32_t>(i), 4);
    put(7, 2);
  }
  put(0, 4);
  put(1, 4);
  return out;
}

TEST(PlyReader, ReadsBinaryBigEndianWithOtherPropertiesAndElements) {
  auto r = ply(big_endian_ply());
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh, kTetrahedron);
  EXPECT_EQ(r->info.format, MeshFormat::ply_binary_big_endian);
  EXPECT_EQ(r->info.faces, 4);
}

TEST(PlyReader, ReadsAsciiWithIntegerCoordinatesQuadsAndSkippedLists) {
  auto r =
      ply("ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty int x\r\nproperty short y\r\n"
          "property double z\r\nproperty list uchar float uv\r\nelement face 1\r\n"
          "property list uchar int vertex_index\r\nend_header\r\n"
          "0 0 0 2 0.5 0.5\r\n1 0 0 0\r\n1 1 0 1 7\r\n0 1 0 0\r\n4 0 1 2 3\r\n");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.triangles, (std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(r->mesh.vertices[2], (Vec3{1, 1, 0}));
  EXPECT_EQ(r->info.faces, 1);
}

TEST(PlyReader, RejectsMalformedFiles) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  struct Case {
    std::string text;
    ErrorKind kind;
    std::int64_t line;  // 0: binary or no line
  };
  const Case cases[] = {
      {"", ErrorKind::parse, 1},
      {"plx\n", ErrorKind::parse, 1},
      {"ply\nformat ascii 1.0\nelement vertex 3\n", ErrorKind::parse, 3},  // no end_header
      {"ply\nformat ascii 2.0\nend_header\n", ErrorKind::unsupported, 2},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
       "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
       ErrorKind::unsupported, 0},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n", ErrorKind::parse,
       4},
      {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n",
       ErrorKind::degenerate, 0},                              // no face element
      {header + "0 0 0\n1 0 0\n0 1\n", ErrorKind::parse, 12},  // truncated
      {header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", ErrorKind::parse, 13},
      {header + "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", ErrorKind::parse, 11},
      {header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", ErrorKind::invalid_value, 11},
      {header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", ErrorKind::invalid_value, 13},
      {header + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ErrorKind::degenerate, 13},
      {header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n9\n", ErrorKind::parse, 14},  // wrong count
      {header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n", ErrorKind::parse, 13},
  };
  for (const Case& c : cases) {
    auto r = ply(c.text);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().kind, c.kind) << c.text << "\n" << r.error().what();
    if (c.line > 0) {
      EXPECT_EQ(r.error().line, c.line) << c.text << "\n" << r.error().what();
    }
  }
}

TEST(PlyReader, RejectsTruncatedBinaryDataWithTheByteOffset) {
  const std::string bytes = big_endian_ply();
  auto r = ply(bytes.substr(0, bytes.size() - 3));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::parse);
  EXPECT_NE(r.error().message.find("byte offset"), std::string::npos) << r.error().message;
  auto longer = ply(bytes + "xy");
  ASSERT_FALSE(longer.ok());
  EXPECT_EQ(longer.error().kind, ErrorKind::parse);
}

TEST(PlyReader, RejectsBinaryIndicesOutOfRangeAndNaN) {
  Mesh bad = kTetrahedron;
  bad.triangles[2][1] = 4;
  auto r = ply(format_mesh(bad, MeshFormat::ply_binary_little_endian));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(r.error().message.find("byte offset"), std::string::npos);
  Mesh nan = kTetrahedron;
  nan.vertices[3].z = std::numeric_limits<double>::quiet_NaN();
  auto n = ply(format_mesh(nan, MeshFormat::ply_binary_little_endian));
  ASSERT_FALSE(n.ok());
  EXPECT_EQ(n.error().kind, ErrorKind::invalid_value);
}

// Regression (bad-input table, "files larger than memory"): an element without properties
// whose header claims 10^12 rows made the reader count through them all (a hang).
TEST(PlyReader, ElementWithoutPropertiesAndAHugeCountIsSkippedAtOnce) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement junk 1000000000000\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  auto r = ply(text);
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
}

}  // namespace
}  // namespace contain::io
