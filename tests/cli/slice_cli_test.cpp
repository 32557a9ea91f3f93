// contain slice, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

// Two unit cubes stacked along z in one file: [0,1]^2 x [0,1] and [0,1]^2 x [1,2].
std::string stacked_cubes_off() {
  std::string out = "OFF\n16 24 0\n";
  for (int box = 0; box < 2; ++box) {
    for (int i = 0; i < 8; ++i) {
      out += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
             std::to_string(((i >> 2) & 1) + box) + "\n";
    }
  }
  const char* faces[12] = {"0 2 3", "0 3 1", "4 5 7", "4 7 6", "0 1 5", "0 5 4",
                           "2 6 7", "2 7 3", "0 4 6", "0 6 2", "1 3 7", "1 7 5"};
  for (int box = 0; box < 2; ++box) {
    for (const char* f : faces) {
      int a = 0, b = 0, c = 0;
      std::sscanf(f, "%d %d %d", &a, &b, &c);
      out += "3 " + std::to_string(a + 8 * box) + " " + std::to_string(b + 8 * box) + " " +
             std::to_string(c + 8 * box) + "\n";
    }
  }
  return out;
}

TEST(SliceCli, WktLinesGiveEachPlaneInTheOrderGiven) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(2.0));
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--z", "1.5", "--z", "-1", "--z", "2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            // The crossings of the side faces' diagonals stay vertices: each edge lies on one
            // triangle.
            "1.5\tMULTIPOLYGON (((0 0, 1.5 0, 2 0, 2 1.5, 2 2, 1.5 2, 0 2, 0 1.5, 0 0)))\n"
            "-1\tMULTIPOLYGON EMPTY\n"
            "2\tMULTIPOLYGON EMPTY\n");
}

TEST(SliceCli, StackedBoxesCutAtTheSharedFaceGiveTheSquare) {
  TempDir dir;
  const std::string mesh = dir.write("stacked.off", stacked_cubes_off());
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--z", "1", "--z", "2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            "1\tMULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)))\n"
            "2\tMULTIPOLYGON EMPTY\n");
}

TEST(SliceCli, LayersAreRoundedOnceAndStopBeforeTheFirstAboveTo) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  // 0.1 + 2 * 0.1 rounded once is 0.30000000000000004 > 0.3: two planes, not three.
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--layers", "0.1,0.1,0.3"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            "0.1\tMULTIPOLYGON (((0 0, 0.1 0, 1 0, 1 0.1, 1 1, 0.1 1, 0 1, 0 0.1, 0 0)))\n"
            "0.2\tMULTIPOLYGON (((0 0, 0.2 0, 1 0, 1 0.2, 1 1, 0.2 1, 0 1, 0 0.2, 0 0)))\n");
  const CliRun all = run_contain({"slice", "--mesh", mesh, "--layers", "0,0.25,1"});
  EXPECT_EQ(all.out.substr(0, all.out.find('\t')), "0");
  EXPECT_NE(all.out.find("\n1\tMULTIPOLYGON EMPTY\n"), std::string::npos) << all.out;
}

TEST(SliceCli, AxesNameTheirPlaneCoordinates) {
  TempDir dir;
  const std::string mesh =
      dir.write("box.off",
                "OFF\n8 12 0\n0 0 0\n1 0 0\n0 2 0\n1 2 0\n0 0 3\n1 0 3\n0 2 3\n1 2 3\n"
                "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n"
                "3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n");
  // --axis x: (y, z), a 2 x 3 rectangle; --axis y: (z, x), 3 x 1.
  const CliRun x = run_contain({"slice", "--mesh", mesh, "--axis", "x", "--z", "0.5"});
  EXPECT_EQ(x.out, "0.5\tMULTIPOLYGON (((0 0, 1 0, 2 0, 2 1.5, 2 3, 1 3, 0 3, 0 1.5, 0 0)))\n")
      << x.err;
  const CliRun y = run_contain({"slice", "--mesh", mesh, "--axis", "y", "--z", "1"});
  EXPECT_EQ(y.out, "1\tMULTIPOLYGON (((0 0, 1.5 0, 3 0, 3 0.5, 3 1, 1.5 1, 0 1, 0 0.5, 0 0)))\n")
      << y.err;
}

TEST(SliceCli, JsonLinesCarryTheTriangleOfEveryEdge) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--z", "0.5", "--json"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.out.rfind("{\"value\":0.5,\"wkt\":\"MULTIPOLYGON (((", 0), 0U) << run.out;
  const auto at = run.out.find("\"triangles\":[[");
  ASSERT_NE(at, std::string::npos) << run.out;
  // The four side faces of cube_off are triangles 4..11; each edge lies on one of them.
  const std::string list = run.out.substr(at + 14, run.out.find("]]") - at - 14);
  int edges = 0;
  for (std::size_t p = 0; p < list.size();) {
    const int t = std::stoi(list.substr(p));
    EXPECT_GE(t, 4);
    EXPECT_LE(t, 11);
    ++edges;
    p = list.find(',', p);
    if (p == std::string::npos) break;
    ++p;
  }
  EXPECT_GE(edges, 4);
}

TEST(SliceCli, GeojsonIsAFeatureCollectionWithValuesAndSvgDrawsEveryLevel) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const CliRun g =
      run_contain({"slice", "--mesh", mesh, "--layers", "0.25,0.25,0.75", "--format", "geojson"});
  EXPECT_EQ(g.exit_code, 0) << g.err;
  EXPECT_EQ(g.out.rfind("{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\","
                        "\"properties\":{\"value\":0.25},\"geometry\":{\"type\":\"MultiPolygon\"",
                        0),
            0U)
      << g.out;
  EXPECT_NE(g.out.find("\"value\":0.75"), std::string::npos);
  const CliRun s =
      run_contain({"slice", "--mesh", mesh, "--layers", "0.25,0.25,0.75", "--format", "svg"});
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.out.find("<svg"), std::string::npos);
  EXPECT_NE(s.out.find("#440154"), std::string::npos) << "the lowest level's colour";
  EXPECT_NE(s.out.find("#fde725"), std::string::npos) << "the highest level's colour";
}

TEST(SliceCli, ShadowIsOneMultipolygon) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--shadow"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)))\n");
  const CliRun g = run_contain({"slice", "--mesh", mesh, "--shadow", "--format", "geojson"});
  EXPECT_EQ(g.out.rfind("{\"type\":\"MultiPolygon\"", 0), 0U) << g.out;
}

TEST(SliceCli, ThreadCountsGiveTheSameBytes) {
  TempDir dir;
  const std::string mesh = dir.write("stacked.off", stacked_cubes_off());
  const CliRun one = run_contain(
      {"slice", "--mesh", mesh, "--layers", "-0.5,0.125,2.5", "--json", "--threads", "1"});
  const CliRun two = run_contain(
      {"slice", "--mesh", mesh, "--layers", "-0.5,0.125,2.5", "--json", "--threads", "2"});
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
}

// 5,001 planes are written in several blocks (64 planes first, then sized by their points):
// every line is the one the plane gives alone, in order, and GeoJSON's features are joined by
// single commas across blocks. --quiet is accepted (no progress off a terminal anyway).
TEST(SliceCli, ManyPlanesStreamedInBlocksAreThePlanesOneByOne) {
  TempDir dir;
  const std::string mesh = dir.write("stacked.off", stacked_cubes_off());
  const CliRun run = run_contain(
      {"slice", "--mesh", mesh, "--layers", "-0.25,0.0005,2.25", "--threads", "2", "--quiet"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  std::size_t lines = 0;
  for (const char c : run.out)
    lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, 5001U);
  // Lines from the first block, the second and the last, each the line of its value alone.
  std::vector<std::string> lines_of_run;
  for (std::size_t at = 0; at < run.out.size();) {
    const std::size_t end = run.out.find('\n', at);
    lines_of_run.push_back(run.out.substr(at, end + 1 - at));
    at = end + 1;
  }
  for (const std::size_t k : {std::size_t{0}, std::size_t{63}, std::size_t{64}, std::size_t{2500},
                              std::size_t{3001}, std::size_t{5000}}) {
    ASSERT_LT(k, lines_of_run.size());
    const std::string value = lines_of_run[k].substr(0, lines_of_run[k].find('\t'));
    const CliRun alone = run_contain({"slice", "--mesh", mesh, "--z", value});
    EXPECT_EQ(alone.out, lines_of_run[k]) << k;
  }
  const CliRun g = run_contain(
      {"slice", "--mesh", mesh, "--layers", "-0.25,0.0005,2.25", "--format", "geojson"});
  EXPECT_EQ(g.exit_code, 0) << g.err;
  EXPECT_EQ(g.out.find(",,"), std::string::npos);
  EXPECT_EQ(g.out.find("[,"), std::string::npos);
  EXPECT_EQ(g.out.substr(g.out.size() - 3), "]}\n");
}

TEST(SliceCli, AnOpenMeshIsBadInputForSectionsNamingTheFileAndTheEdgeButCastsAShadow) {
  TempDir dir;
  const std::string mesh = dir.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--z", "0"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("tri.off"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("not closed"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("(0 0 0) -> (1 0 0)"), std::string::npos) << run.err;
  // A shadow needs no solid: the open triangle's is the triangle (the union of its projection).
  const CliRun shadow = run_contain({"slice", "--mesh", mesh, "--shadow"});
  EXPECT_EQ(shadow.exit_code, 0) << shadow.err;
  EXPECT_EQ(shadow.out, "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)))\n");
}

TEST(SliceCli, BadLayersAreBadInputNamingTheOptionAndMisuseIsAUsageError) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  for (const char* layers : {"0,0,1", "0,-1,1", "0,nan,1", "0,1e-9,1", "nan,1,2", "0,1,inf"}) {
    const CliRun run = run_contain({"slice", "--mesh", mesh, "--layers", layers});
    EXPECT_EQ(run.exit_code, 3) << layers;
    EXPECT_NE(run.err.find("--layers"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty());
  }
  const CliRun nan = run_contain({"slice", "--mesh", mesh, "--z", "nan"});
  EXPECT_EQ(nan.exit_code, 3);
  EXPECT_NE(nan.err.find("--z"), std::string::npos) << nan.err;
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--z", "x"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--layers", "0,1"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--z", "1", "--layers", "0,1,2"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--shadow", "--z", "1"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--z", "1", "--axis", "w"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--mesh", mesh, "--z", "1", "--format", "png"}).exit_code, 2);
  EXPECT_EQ(run_contain({"slice", "--z", "1"}).exit_code, 2);
  const CliRun missing = run_contain({"slice", "--mesh", "/nonexistent.off", "--z", "1"});
  EXPECT_EQ(missing.exit_code, 3);
}

}  // namespace
}  // namespace contain::test
