// contain clip on solids (--subject MESH [--clip MESH ...] --op OP, --csg FILE), end to end, per
// ../shared/spec/cli.md "Solids: booleans of meshes": bad input first (refused before any
// boolean runs), then results read back and checked exactly.

#include <gtest/gtest.h>

#include <gmpxx.h>

#include <string>
#include <vector>

#include "cli/run.h"
#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_closure.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// The box [lo, hi]^3 as a closed, outward OFF mesh (corner i at bit 0: x, bit 1: y, bit 2: z).
std::string box_off(double lo, double hi, const std::string& header = "OFF") {
  std::string out = header + "\n8 12 0\n";
  for (int i = 0; i < 8; ++i) {
    for (int axis = 0; axis < 3; ++axis)
      out += std::to_string((i >> axis) & 1 ? hi : lo) + (axis < 2 ? " " : "\n");
  }
  return out +
         "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n"
         "3 0 6 2\n3 1 3 7\n3 1 7 5\n";
}

// The unit box with its last triangle (1 7 5) missing: the directed edges 7->1, 5->7 and 1->5
// of the triangles around the hole have no reverse.
std::string open_box_off() {
  std::string text = box_off(0, 1);
  text.replace(text.find("8 12 0"), 6, "8 11 0");
  text.erase(text.rfind("3 1 7 5\n"));
  return text;
}

// --- bad input and usage: refused before any boolean runs ---------------------------------------

TEST(ClipSolidCli, OpenMeshIsExit3NamingTheFileTheEdgeAndItsTriangle) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", box_off(0, 1));
  const std::string open = dir.write("open.off", open_box_off());
  const CliRun run = run_contain({"clip", "--subject", cube, "--clip", open, "--op", "union"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_TRUE(has(run.err, open + ": not closed")) << run.err;
  // The edge named is the one shapes::unmatched_edge picks, with its triangle.
  EXPECT_TRUE(has(run.err, "the directed edge (")) << run.err;
  EXPECT_TRUE(has(run.err, "of triangle ")) << run.err;
  auto mesh = io::read_mesh(open);
  ASSERT_TRUE(mesh.ok());
  const auto edge = unmatched_edge(mesh->mesh);
  ASSERT_TRUE(edge.has_value());
  const std::string words = "(" + std::to_string(static_cast<int>(edge->from.x)) + " " +
                            std::to_string(static_cast<int>(edge->from.y)) + " " +
                            std::to_string(static_cast<int>(edge->from.z)) + ") -> (" +
                            std::to_string(static_cast<int>(edge->to.x)) + " " +
                            std::to_string(static_cast<int>(edge->to.y)) + " " +
                            std::to_string(static_cast<int>(edge->to.z)) + ") of triangle " +
                            std::to_string(edge->triangle) + " ";
  EXPECT_TRUE(has(run.err, words)) << run.err << "\nexpected: " << words;
}

TEST(ClipSolidCli, OpenSubjectAloneIsExit3Too) {
  TempDir dir;
  const std::string open = dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CliRun run = run_contain({"clip", "--subject", open, "--op", "union"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, open + ": not closed: the directed edge (0 0 0) -> (1 0 0) of "
                                  "triangle 0 "))
      << run.err;
}

TEST(ClipSolidCli, NonFiniteCoordinatesAreExit3NamingTheFileInEveryFormat) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", box_off(0, 1));
  const std::vector<std::pair<std::string, std::string>> files = {
      {"nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\nnan 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"},
      {"big.off",
       "OFF\n4 4 0\n0 0 0\n1e999 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n"
       "3 0 3 2\n"},
      {"nan.stl",
       "solid s\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex nan 1 0\n"
       "vertex 1 0 0\nendloop\nendfacet\nendsolid s\n"},
      {"inf.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
       "end_header\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n"}};
  for (const auto& [name, text] : files) {
    const std::string path = dir.write(name, text);
    const CliRun run = run_contain({"clip", "--subject", cube, "--clip", path, "--op", "union"});
    EXPECT_EQ(run.exit_code, 3) << name << ": " << run.err;
    EXPECT_TRUE(has(run.err, path)) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

TEST(ClipSolidCli, UnreadableOrMalformedMeshIsExit3) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", box_off(0, 1));
  const std::string bad = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_EQ(run_contain({"clip", "--subject", cube, "--clip", bad, "--op", "union"}).exit_code, 3);
  const std::string missing = (dir.path() / "missing.stl").string();
  const CliRun run = run_contain({"clip", "--subject", missing, "--op", "union"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, missing)) << run.err;
}

TEST(ClipSolidCli, UsageErrorsAreExit2) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 1));
  const std::string b = dir.write("b.off", box_off(0.5, 2));
  const std::string region = dir.write("r.wkt", "POLYGON((0 0,1 0,1 1,0 0))");
  const std::string out = (dir.path() / "r.obj").string();
  const std::vector<std::vector<std::string>> cases = {
      {"--subject", a, "--clip", b},                             // no --op
      {"--subject", a, "--op", "difference"},                    // one solid, not union
      {"--subject", a, "--clip", region, "--op", "union"},       // a region beside a mesh
      {"--subject", a, "--clip", b, "--op", "union", "--json"},  // --json without --out
      {"--subject", a, "--clip", b, "--op", "union", "--out", (dir.path() / "r.wkt").string()},
      {"--subject", a, "--clip", b, "--op", "union", "--fill", "nonzero"},
      {"--subject", a, "--clip", b, "--op", "union", "--format", "svg"},
      {"--subject", a, "--clip", b, "--op", "union", "--box", "0,0,0,1,1,1"},
      {"--subject", a, "--clip", b, "--op", "union", "--cap"},
      {"--subject", a, "--clip", b, "--op", "merge"},
      {"--csg", a, "--subject", a, "--op", "union"},    // --csg is the whole tree
      {a, b, "--subject", a, "--op", "union"},          // A B and --subject
      {"--mesh", a, "--box", "0,0,0,1,1,1", "--json"},  // --json of the solids only
      {"--subject", region, "--clip", region, "--clip", region, "--op", "union"}};  // polygons: one
  for (std::vector<std::string> args : cases) {
    args.insert(args.begin(), "clip");
    const CliRun run = run_contain(args);
    std::string line;
    for (const std::string& arg : args)
      line += arg + " ";
    EXPECT_EQ(run.exit_code, 2) << line << "\n" << run.err;
    EXPECT_TRUE(run.out.empty()) << line << "\n" << run.out;
    EXPECT_FALSE(run.err.empty()) << line;
  }
  // Nothing was written where --out was refused.
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ClipSolidCli, CsgLeafThatIsNotPolyhedralIsExit3NamingIt) {
  TempDir dir;
  static_cast<void>(dir.write("a.off", box_off(0, 1)));
  const std::string sphere = dir.write(
      "s.json",
      R"({"difference": [{"mesh": "a.off"}, {"union": [{"box": {"min": [0,0,0], "max": [1,1,1]}},)"
      R"( {"sphere": {"center": [0, 0, 0], "radius": 0.5}}]}]})");
  CliRun run = run_contain({"clip", "--csg", sphere});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "difference[1].union[1].sphere: a sphere is not polyhedral")) << run.err;
  EXPECT_TRUE(has(run.err, sphere)) << run.err;
  const std::string implicit = dir.write("i.json", R"({"implicit": "1 - x^2 - y^2 - z^2"})");
  run = run_contain({"clip", "--csg", implicit});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "implicit: an implicit function is not polyhedral")) << run.err;
}

TEST(ClipSolidCli, UnboundedCsgTreeIsExit3) {
  TempDir dir;
  const std::string half = dir.write(
      "h.json",
      R"({"union": [{"box": {"min": [0,0,0], "max": [1,1,1]}}, {"halfspace": [0,0,1,0]}]})");
  const CliRun run = run_contain({"clip", "--csg", half});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "unbounded")) << run.err;
}

TEST(ClipSolidCli, MalformedCsgIsExit3NamingTheFile) {
  TempDir dir;
  const std::string bad = dir.write("bad.json", R"({"union": [)");
  const CliRun run = run_contain({"clip", "--csg", bad});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, bad)) << run.err;
}

// --- results (the engine end to end) -------------------------------------------------------------

// Reads a written mesh and checks the contract: closed, and the volume exactly `volume`.
void expect_solid(const std::string& path, const mpq_class& volume) {
  auto mesh = io::read_mesh(path, {.allow_empty = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().what();
  EXPECT_FALSE(unmatched_edge(mesh->mesh).has_value()) << path;
  EXPECT_EQ(exact_volume(mesh->mesh), volume) << path;
}

TEST(ClipSolidCli, BoxMinusBoxHasTheExactVolumeAndIsClosed) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 2));
  const std::string b = dir.write("b.off", box_off(1, 3));
  const std::string out = (dir.path() / "r.obj").string();
  const CliRun run = run_contain(
      {"clip", "--subject", a, "--clip", b, "--op", "difference", "--out", out, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "\"volume\":7,")) << run.out;
  EXPECT_TRUE(has(run.out, "\"shells\":1,")) << run.out;
  EXPECT_TRUE(has(run.out, "\"moved\":0}")) << run.out;
  expect_solid(out, 7);
}

TEST(ClipSolidCli, EveryOpOfTwoOverlappingBoxesHasItsExactVolume) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 2));
  const std::string b = dir.write("b.off", box_off(1, 3));
  const std::vector<std::pair<std::string, int>> ops = {
      {"union", 15}, {"intersection", 1}, {"difference", 7}, {"xor", 14}};
  for (const auto& [op, volume] : ops) {
    const std::string out = (dir.path() / (op + ".off")).string();
    const CliRun run = run_contain({"clip", "--subject", a, "--clip", b, "--op", op, "--out", out});
    ASSERT_EQ(run.exit_code, 0) << op << ": " << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    expect_solid(out, volume);
  }
}

TEST(ClipSolidCli, ManyClipsAreOneBooleanAndTheDefaultOutputIsOffOnStdout) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 4));
  const std::string b = dir.write("b.off", box_off(3, 5));
  const std::string c = dir.write("c.off", box_off(-1, 1));
  const CliRun run =
      run_contain({"clip", "--subject", a, "--clip", b, "--clip", c, "--op", "difference"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.out.rfind("OFF\n", 0), 0u) << run.out;
  expect_solid(dir.write("r.off", run.out), 64 - 1 - 1);
}

TEST(ClipSolidCli, EmptyMeshIsTheEmptySolidAndAnEmptyResultHasNoFaces) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 1));
  const std::string empty = dir.write("empty.off", "OFF\n0 0 0\n");
  CliRun run = run_contain({"clip", "--subject", a, "--clip", empty, "--op", "intersection"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto mesh = io::parse_mesh(run.out, io::MeshFormat::off, "stdout", {.allow_empty = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().what();
  EXPECT_TRUE(mesh->mesh.triangles.empty());
  run = run_contain({"clip", "--subject", empty, "--clip", a, "--op", "union"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  expect_solid(dir.write("u.off", run.out), 1);
}

TEST(ClipSolidCli, RepairOfTwoOverlappingShellsInOneFileCountsThemOnce) {
  TempDir dir;
  // Two boxes in one OFF: [0, 2]^3 and [1, 3]^3 overlap in a unit cube.
  std::string two = box_off(0, 2);
  const std::string second = box_off(1, 3);
  std::string text = "OFF\n16 24 0\n";
  const auto lines = [](const std::string& off) {
    std::vector<std::string> out;
    std::size_t at = 0;
    for (std::size_t next; (next = off.find('\n', at)) != std::string::npos; at = next + 1)
      out.push_back(off.substr(at, next - at));
    return out;
  };
  const auto l1 = lines(two), l2 = lines(second);
  for (int i = 2; i < 10; ++i)
    text += l1[i] + "\n";
  for (int i = 2; i < 10; ++i)
    text += l2[i] + "\n";
  for (int i = 10; i < 22; ++i)
    text += l1[i] + "\n";
  for (int i = 10; i < 22; ++i) {
    int n, p, q, r;
    std::sscanf(l2[i].c_str(), "%d %d %d %d", &n, &p, &q, &r);
    text += "3 " + std::to_string(p + 8) + " " + std::to_string(q + 8) + " " +
            std::to_string(r + 8) + "\n";
  }
  const std::string both = dir.write("both.off", text);
  const std::string out = (dir.path() / "repaired.ply").string();
  const CliRun run =
      run_contain({"clip", "--subject", both, "--op", "union", "--out", out, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "\"volume\":15,")) << run.out;
  expect_solid(out, 15);
}

TEST(ClipSolidCli, CsgBoxCutByAHalfSpaceMinusAMeshIsOneValidMesh) {
  TempDir dir;
  static_cast<void>(dir.write("hole.off", box_off(0.25, 0.5)));
  const std::string tree = dir.write(
      "t.json", R"({"difference": [{"intersection": [{"box": {"min": [0,0,0], "max": [1,1,1]}},)"
                R"( {"halfspace": [0, 0, -1, 0.75]}]}, {"mesh": "hole.off"}]})");
  const std::string out = (dir.path() / "t.off").string();
  const CliRun run = run_contain({"clip", "--csg", tree, "--out", out, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // z <= 0.75 inside the unit box, minus the cube [0.25, 0.5]^3: 3/4 - 1/64.
  expect_solid(out, mpq_class(3, 4) - mpq_class(1, 64));
}

// A mesh file without faces in a CSG tree is the empty solid: the union with it is the box.
TEST(ClipSolidCli, CsgLeafWithoutFacesIsTheEmptySolid) {
  TempDir dir;
  static_cast<void>(dir.write("empty.off", "OFF\n0 0 0\n"));
  const std::string tree = dir.write(
      "t.json", R"({"union": [{"box": {"min": [0,0,0], "max": [2,2,2]}}, {"mesh": "empty.off"}]})");
  const std::string out = (dir.path() / "t.off").string();
  const CliRun run = run_contain({"clip", "--csg", tree, "--out", out});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  expect_solid(out, 8);
}

TEST(ClipSolidCli, PositionalShapesWorkForMeshesToo) {
  TempDir dir;
  const std::string a = dir.write("a.off", box_off(0, 2));
  const std::string b = dir.write("b.off", box_off(1, 3));
  const CliRun run = run_contain({"clip", a, b, "--op", "intersection"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  expect_solid(dir.write("r.off", run.out), 1);
}

}  // namespace
}  // namespace contain::test
