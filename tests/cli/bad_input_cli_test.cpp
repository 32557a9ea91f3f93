// The bad-input contract of issue 6, one test per row of the table in docs/robustness.md
// ("Bad input"): every malformed, hostile or degenerate input gives exit 3 and a message naming
// the file and its line or byte, or the documented result, and never a crash, a hang or an
// allocation the file cannot justify.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "cli/run.h"

namespace contain::test {
namespace {

// Bytes of a binary STL: an 80-byte header, the triangle count it claims, then `records` records
// of 50 bytes (all zero: degenerate triangles at the origin).
std::string binary_stl(std::uint32_t claimed, std::size_t records) {
  std::string bytes(80, 'x');
  for (int i = 0; i < 4; ++i)
    bytes += static_cast<char>((claimed >> (8 * i)) & 0xff);
  bytes.append(50 * records, '\0');
  return bytes;
}

TEST(BadInputCli, MalformedNumbersAreExitThreeNamingFileAndLine) {
  TempDir dir;
  const std::string square = dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4))");
  const std::string points = dir.write("p.txt", "0 0\n1 2x\n");
  CliRun run = run_contain({"inside", "--polygon", square, "--points", points});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(run.out.empty());
  EXPECT_TRUE(has(run.err, "p.txt:2")) << run.err;

  const std::string off = dir.write("m.off", "OFF\n3 1 0\n0 0 0\n1 0 zz\n0 1 0\n3 0 1 2\n");
  run = run_contain({"bound", off});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "m.off:4")) << run.err;

  const std::string wkt = dir.write("bad.wkt", "POLYGON ((0 0, 1 0,\n 1 1.2.3, 0 0))");
  run = run_contain({"inside", "--polygon", wkt}, "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "bad.wkt:2")) << run.err;

  const std::string json =
      dir.write("bad.geojson", "{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, -]]]}");
  run = run_contain({"inside", "--polygon", json}, "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "bad.geojson:2")) << run.err;

  run = run_contain({"clip", "--segments", dir.write("s.txt", "0 0 1 one\n"), "--box", "0,0,1,1"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "s.txt:1")) << run.err;
}

TEST(BadInputCli, TruncatedBinaryFilesAreExitThreeNamingTheBytes) {
  TempDir dir;
  // Two triangles announced, one and a bit present.
  const std::string stl = dir.write("t.stl", binary_stl(2, 1) + std::string(10, '\0'));
  CliRun run = run_contain({"bound", stl});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "t.stl")) << run.err;
  EXPECT_TRUE(has(run.err, "truncated")) << run.err;
  EXPECT_TRUE(has(run.err, "byte")) << run.err;

  const std::string ply = dir.write(
      "t.ply",
      std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n") +
          std::string(20, '\0'));
  run = run_contain({"bound", ply});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "t.ply")) << run.err;
  EXPECT_TRUE(has(run.err, "byte offset")) << run.err;
}

TEST(BadInputCli, WrongCountsAreExitThreeNamingTheLine) {
  TempDir dir;
  // The header announces 4 vertices; 3 follow before the faces.
  const std::string off = dir.write("short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CliRun run = run_contain({"bound", off});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "short.off:")) << run.err;

  // More faces than announced: trailing data.
  const std::string extra = dir.write(
      "extra.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
  run = run_contain({"bound", extra});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "extra.ply")) << run.err;

  // A point line of three numbers in a 2D point file.
  const std::string square = dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4))");
  run = run_contain({"inside", "--polygon", square}, "1 1\n1 1 1\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "<stdin>:2")) << run.err;
}

TEST(BadInputCli, IndicesOutOfRangeAreExitThreeNamingTheLine) {
  TempDir dir;
  CliRun run = run_contain({"bound", dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "m.obj:4")) << run.err;

  run = run_contain({"bound", dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")});
  EXPECT_EQ(run.exit_code, 3);  // OBJ indices start at 1
  EXPECT_TRUE(has(run.err, "zero.obj:4")) << run.err;

  run = run_contain({"bound", dir.write("m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "m.off:6")) << run.err;
}

TEST(BadInputCli, NanAndInfAreExitThreeNamingFileAndLine) {
  TempDir dir;
  const std::string square = dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4))");
  for (const char* bad : {"nan 0", "1 inf", "-inf 0", "1e400 0"}) {
    const CliRun run =
        run_contain({"inside", "--polygon", square}, std::string("0 0\n") + bad + "\n");
    EXPECT_EQ(run.exit_code, 3) << bad;
    EXPECT_TRUE(has(run.err, "<stdin>:2")) << bad << ": " << run.err;
  }
  CliRun run = run_contain({"bound", dir.write("m.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "m.obj:2")) << run.err;

  run = run_contain({"inside", "--polygon", dir.write("inf.wkt", "POLYGON ((0 0, 1 0, 1 1e999))")},
                    "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "inf.wkt:1")) << run.err;

  run = run_contain({"clip", "--segments", dir.write("s.txt", "nan 0 1 1\n"), "--box", "0,0,2,2"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "s.txt:1")) << run.err;

  // A binary STL float that is NaN: the message names the byte offset.
  std::string stl = binary_stl(1, 1);
  stl[84 + 12] = '\0';
  stl[84 + 12 + 2] = static_cast<char>(0xc0);
  stl[84 + 12 + 3] = static_cast<char>(0x7f);  // 0x7fc00000: a quiet NaN
  run = run_contain({"bound", dir.write("nan.stl", stl)});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "byte offset 96")) << run.err;
}

TEST(BadInputCli, EmptyShapesAreExitThreeOrTheDocumentedEmptyResult) {
  TempDir dir;
  CliRun run = run_contain({"bound", dir.write("empty.obj", "")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "empty.obj")) << run.err;

  run = run_contain({"bound", dir.write("nofaces.off", "OFF\n0 0 0\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "nofaces.off")) << run.err;

  // An empty region is valid: it contains nothing.
  const std::string empty = dir.write("empty.wkt", "POLYGON EMPTY");
  run = run_contain({"inside", "--polygon", empty}, "0 0\n1 1\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "out\nout\n");

  const std::string square = dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4))");
  run = run_contain({"clip", "--subject", empty, "--clip", square, "--op", "intersection"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "EMPTY")) << run.out;

  // No points: no output lines.
  run = run_contain({"inside", "--polygon", square, "--points", dir.write("none.txt", "# none\n")});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());

  // A ring of fewer than 3 distinct points is degenerate.
  run = run_contain({"inside", "--polygon", dir.write("two.wkt", "POLYGON ((0 0, 1 1, 0 0))")},
                    "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "two.wkt")) << run.err;
}

TEST(BadInputCli, ZeroAreaPolygonsEncloseNothing) {
  TempDir dir;
  // Collinear ring: its edges bound no filled sector, so even its own points are `out`.
  const std::string flat = dir.write("flat.wkt", "POLYGON ((0 0, 1 1, 2 2, 0 0))");
  CliRun run = run_contain({"inside", "--polygon", flat}, "1 1\n0.5 0.5\n5 5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "out\nout\nout\n");

  const std::string square = dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4))");
  run = run_contain({"clip", "--subject", square, "--clip", flat, "--op", "union"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n");
  run = run_contain({"clip", "--subject", flat, "--clip", square, "--op", "intersection"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "EMPTY")) << run.out;
}

TEST(BadInputCli, ZeroLengthSegmentsAreClippedAsPoints) {
  TempDir dir;
  const std::string segments = dir.write("s.txt", "1 1 1 1\n5 5 5 5\n2 2 2 2\n");
  for (const char* algorithm : {"cohen-sutherland", "liang-barsky", "cyrus-beck"}) {
    const CliRun run =
        run_contain({"clip", "--segments", segments, "--box", "0,0,2,2", "--algorithm", algorithm});
    EXPECT_EQ(run.exit_code, 0) << algorithm << ": " << run.err;
    // Inside: kept as the point; outside: nothing; on the corner: kept.
    EXPECT_EQ(run.out, "1 1 1 1\n-\n2 2 2 2\n") << algorithm;
  }
}

TEST(BadInputCli, NonClosedMeshesWarnOrAreRefusedWhereAClosedOneIsNeeded) {
  TempDir dir;
  const std::string open = dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // Containment answers from the generalized winding number, and says so.
  CliRun run = run_contain({"inside", "--mesh", open}, "0.2 0.2 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "on\n");
  EXPECT_TRUE(has(run.err, "not closed")) << run.err;
  // Capping a cut needs a closed solid.
  run = run_contain({"clip", "--mesh", open, "--halfspace", "1,0,0,-0.5", "--cap"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "open.obj")) << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST(BadInputCli, HugeAndTinyCoordinatesAreExact) {
  TempDir dir;
  const std::string huge =
      dir.write("huge.wkt", "POLYGON ((-1e300 -1e300, 1e300 -1e300, 1e300 1e300, -1e300 1e300))");
  CliRun run = run_contain({"inside", "--polygon", huge}, "0 0\n1e300 0\n1e300 1e300\n2e300 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\non\nout\n");

  const std::string tiny =
      dir.write("tiny.wkt", "POLYGON ((0 0, 1e-300 0, 1e-300 1e-300, 0 1e-300))");
  run = run_contain({"inside", "--polygon", tiny},
                    "5e-301 5e-301\n1e-300 5e-301\n2e-300 0\n1e-320 1e-320\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\nin\n");  // 1e-320 is subnormal, still exact

  const std::string mesh = dir.write(
      "huge.obj",
      "v 1e300 0 0\nv -1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
  run = run_contain({"inside", "--mesh", mesh}, "0 1e299 1e299\n0 0 0\n0 -1e299 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\n");
  run = run_contain({"bound", mesh});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "\"radius\":1e+300")) << run.out;
}

TEST(BadInputCli, CountsBeyondTheFileSizeAreRefusedBeforeAllocating) {
  TempDir dir;
  // A binary STL header claiming 2^31 triangles (107 GB) in a 134-byte file.
  CliRun run = run_contain({"bound", dir.write("big.stl", binary_stl(0x80000000u, 1))});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "big.stl")) << run.err;
  EXPECT_TRUE(has(run.err, "2147483648 triangles")) << run.err;

  // A PLY claiming 10^12 vertices, and one claiming 2 * 10^9 (within int32) in a tiny file.
  run = run_contain(
      {"bound", dir.write("big.ply",
                          "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 1\n"
                          "property list uchar int vertex_indices\nend_header\n0 0 0\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "big.ply")) << run.err;
  run = run_contain(
      {"bound", dir.write("big2.ply",
                          "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                          "property float x\nproperty float y\nproperty float z\n"
                          "element face 2000000000\nproperty list uchar int vertex_indices\n"
                          "end_header\n" +
                              std::string(30, '\0'))});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "truncated")) << run.err;

  // An OFF header claiming 10^12 vertices.
  run = run_contain({"bound", dir.write("big.off", "OFF\n1000000000000 1 0\n0 0 0\n")});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "big.off:2")) << run.err;

  // An element without properties claiming 10^12 rows holds no bytes: read at once (it hung).
  run = run_contain(
      {"bound", dir.write("junk.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement junk 1000000000000\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

TEST(BadInputCli, DeeplyNestedFilesAreExitThreeNotAStackOverflow) {
  TempDir dir;
  const int depth = 100000;
  std::string csg;
  for (int i = 0; i < depth; ++i)
    csg += "{\"complement\": ";
  csg += "{\"sphere\": {\"center\": [0, 0, 0], \"radius\": 1}}";
  csg.append(depth, '}');
  CliRun run = run_contain({"inside", "--csg", dir.write("deep.json", csg)}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "deep.json")) << run.err;
  EXPECT_TRUE(has(run.err, "nested")) << run.err;

  std::string geojson;
  for (int i = 0; i < depth; ++i)
    geojson += "{\"type\":\"GeometryCollection\",\"geometries\":[";
  for (int i = 0; i < depth; ++i)
    geojson += "]}";
  run = run_contain({"inside", "--polygon", dir.write("deep.geojson", geojson)}, "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "deep.geojson")) << run.err;
}

TEST(BadInputCli, BinaryGarbageIsExitThreeForEveryFormat) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 4096; ++i)
    garbage += static_cast<char>((i * 7919 + 13) & 0xff);
  for (const char* name : {"g.obj", "g.off", "g.stl", "g.ply"}) {
    const CliRun run = run_contain({"bound", dir.write(name, garbage)});
    EXPECT_EQ(run.exit_code, 3) << name;
    EXPECT_TRUE(has(run.err, name)) << name << ": " << run.err;
  }
  for (const char* name : {"g.wkt", "g.geojson"}) {
    const CliRun run = run_contain({"inside", "--polygon", dir.write(name, garbage)}, "0 0\n");
    EXPECT_EQ(run.exit_code, 3) << name;
    EXPECT_TRUE(has(run.err, name)) << name << ": " << run.err;
  }
  const CliRun run = run_contain({"inside", "--csg", dir.write("g.json", garbage)}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  const CliRun points = run_contain(
      {"inside", "--polygon", dir.write("sq.wkt", "POLYGON ((0 0, 1 0, 1 1))")}, garbage);
  EXPECT_EQ(points.exit_code, 3);
  EXPECT_TRUE(has(points.err, "<stdin>")) << points.err;
}

TEST(BadInputCli, CcdQueryFilesAreExitThreeNamingTheLine) {
  TempDir dir;
  const std::string row = "0,1,0,1,0,1,0\n";
  std::string rows;
  for (int i = 0; i < 8; ++i)
    rows += row;
  // A rational that is not a double (1/3) on the first row of the second query.
  const std::string third =
      dir.write("third.csv", rows + "1,3,0,1,0,1,0\n" + rows.substr(row.size()));
  CliRun run = run_contain({"collide", "--ccd", "vertex-face", "--queries", third});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "third.csv:9:")) << run.err;
  EXPECT_TRUE(has(run.err, "not exactly a double")) << run.err;
  EXPECT_EQ(run.out, "");
  // Six columns; a decimal fraction instead of an integer; a zero denominator.
  for (const auto& [name, bad] :
       {std::pair{"six.csv", "0,1,0,1,0,1\n"}, std::pair{"decimal.csv", "0.5,1,0,1,0,1,0\n"},
        std::pair{"zero.csv", "1,0,0,1,0,1,0\n"}}) {
    const std::string file = dir.write(name, row + row + bad + rows);
    run = run_contain({"collide", "--ccd", "edge-edge", "--queries", file});
    EXPECT_EQ(run.exit_code, 3) << name;
    EXPECT_TRUE(has(run.err, std::string(name) + ":3:")) << run.err;
  }
  // A file that ends inside a query.
  const std::string cut = dir.write("cut.csv", rows + row + row);
  run = run_contain({"collide", "--ccd", "edge-edge", "--queries", cut});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "cut.csv:10:")) << run.err;
  EXPECT_TRUE(has(run.err, "ends inside a query")) << run.err;
  // 24-number files: 23 numbers, or a NaN.
  const std::string short_line =
      dir.write("short.txt", "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
  run = run_contain({"collide", "--ccd", "vertex-face", "--queries", short_line});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "short.txt:1:")) << run.err;
  const std::string nan =
      dir.write("nan.txt", "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 nan\n");
  run = run_contain({"collide", "--ccd", "vertex-face", "--queries", nan});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "nan.txt:1:")) << run.err;
}

TEST(BadInputCli, MotionFilesAreExitThreeNamingTheLine) {
  TempDir dir;
  const std::string cube =
      dir.write("cube.off",
                "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n"
                "3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n");
  const std::string motions = dir.write(
      "m.txt", "1 0 0 0 0 1 0 0 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0\n");
  CliRun run = run_contain({"collide", cube, cube, "--motions", motions});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "m.txt:2:")) << run.err;
  const std::string inf =
      dir.write("inf.txt", "1 0 0 0 0 1 0 0 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1 inf\n");
  run = run_contain({"collide", cube, cube, "--motions", inf});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "inf.txt:1:")) << run.err;
}

// Issue 13: three inputs that were accepted silently.
TEST(BadInputCli, BoxWithItsMinCornerAboveItsMaxIsExitThreeNamingTheOption) {
  TempDir dir;
  const std::string square = dir.write("sq.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"clip", "--polygon", square, "--box", "3,0,1,1"},
           {"clip", "--polygon", square, "--box", "0,3,1,1"},
           {"clip", "--polygon", square, "--tiles", "2,2", "--box", "4,4,0,0"},
           {"clip", "--segments", dir.write("s.txt", "0 0 1 1\n"), "--box", "0,0,1,-1"},
           {"clip", "--mesh", dir.write("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "--box", "0,0,2,1,1,1"}}) {
    const CliRun run = run_contain(args);
    EXPECT_EQ(run.exit_code, 3) << args[4];
    EXPECT_TRUE(run.out.empty());
    EXPECT_TRUE(has(run.err, "--box")) << run.err;
    EXPECT_TRUE(has(run.err, "min corner")) << run.err;
  }
  // A box of zero width is a box: its intersection has no area.
  const CliRun flat = run_contain({"clip", "--polygon", square, "--box", "1,0,1,4"});
  EXPECT_EQ(flat.exit_code, 0) << flat.err;
  EXPECT_EQ(flat.out, "POLYGON EMPTY\n");
}

TEST(BadInputCli, NegativeSphereOrCircleRadiusIsExitThreeNamingTheOption) {
  TempDir dir;
  CliRun run =
      run_contain({"clip", "--segments", dir.write("s2.txt", "0 0 1 1\n"), "--circle", "0,0,-1"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "--circle")) << run.err;
  EXPECT_TRUE(has(run.err, "negative")) << run.err;
  run = run_contain(
      {"clip", "--segments", dir.write("s3.txt", "0 0 0 1 1 1\n"), "--sphere", "0,0,0,-0.5"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "--sphere")) << run.err;
  EXPECT_TRUE(run.out.empty());
  // Radius 0 is the ball of one point.
  run = run_contain({"clip", "--segments", dir.write("s4.txt", "-1 0 1 0\n"), "--circle", "0,0,0"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "0 0 0 0\n");
}

TEST(BadInputCli, UnclosedWktRingIsClosedWithAWarningNamingFileAndLine) {
  TempDir dir;
  const std::string open_ring =
      dir.write("open.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0),\n (1 1, 1 2, 2 2, 2 1))");
  const CliRun run = run_contain({"clip", "--polygon", open_ring, "--box", "0,0,4,4"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.err, "open.wkt:2")) << run.err;
  EXPECT_TRUE(has(run.err, "warning")) << run.err;
  EXPECT_TRUE(has(run.err, "not closed")) << run.err;
  EXPECT_EQ(run.out, "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))\n");
  // Closed rings give no warning.
  const CliRun closed = run_contain({"clip", "--polygon",
                                     dir.write("closed.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))"),
                                     "--box", "0,0,4,4"});
  EXPECT_EQ(closed.err, "");
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

// The rows of the bad-input table for `contain distance` (issue 12).
TEST(BadInputCli, DistanceRefusesNonFiniteInputAndDocumentsEmptyShapes) {
  TempDir dir;
  const std::string cube =
      dir.write("cube.off",
                "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 2 3 7\n3 2 7 6\n"
                "3 1 2 6\n3 1 6 5\n3 0 4 7\n3 0 7 3\n");
  for (const char* bad : {"nan 0 0\n", "0 inf 0\n", "0 0 1e400\n"}) {
    const CliRun run = run_contain({"distance", "--mesh", cube}, std::string("0 0 0\n") + bad);
    EXPECT_EQ(run.exit_code, 3) << bad;
    EXPECT_TRUE(run.out.empty());
    EXPECT_TRUE(has(run.err, ":2")) << run.err;
  }
  const std::string nan_mesh = dir.write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(run_contain({"distance", "--mesh", nan_mesh}, "0 0 0\n").exit_code, 3);
  EXPECT_EQ(run_contain({"distance", nan_mesh, cube}).exit_code, 3);
  const std::string empty = dir.write("empty.off", "");
  EXPECT_EQ(run_contain({"distance", "--mesh", empty}, "0 0 0\n").exit_code, 3);
  // --within D: D must be finite and >= 0 (a usage error otherwise)
  // A bad number is bad input (exit 3, decided in issue 24 after the contract's rule).
  for (const char* d : {"nan", "inf", "-1"})
    EXPECT_EQ(run_contain({"distance", "--mesh", cube, "--within", d}, "0 0 0\n").exit_code, 3);
  const std::string poses = dir.write("poses.txt", "1 0 0 nan 0 1 0 0 0 0 1 0\n");
  const CliRun p = run_contain({"distance", cube, cube, "--poses", poses});
  EXPECT_EQ(p.exit_code, 3);
  EXPECT_TRUE(has(p.err, "poses.txt:1")) << p.err;
  // documented result: the distance to an empty region is infinite, and nothing is within D
  const std::string none = dir.write("none.wkt", "POLYGON EMPTY");
  const CliRun e = run_contain({"distance", "--polygon", none}, "0 0\n");
  EXPECT_EQ(e.exit_code, 0);
  EXPECT_EQ(e.out, "inf\n");
  EXPECT_EQ(run_contain({"distance", "--polygon", none, "--within", "1e300"}, "0 0\n").out, "no\n");
  // 1e300 and 1e-300 coordinates: exact
  const CliRun huge =
      run_contain({"distance", "--polygon",
                   dir.write("big.wkt", "POLYGON ((0 0, 1e300 0, 1e300 1e300, 0 1e300))")},
                  "-3e299 0\n2e-300 1e-300\n");
  EXPECT_EQ(huge.out, "3.0000000000000002e+299\n1e-300\n");  // the doubles 3e299 and 1e-300
}

}  // namespace
}  // namespace contain::test
