#include "contain/io/csg_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "contain/inside/csg.h"

namespace contain::io {
namespace {

using inside::CsgSolid;

Result<CsgSolid> solid_of(std::string_view text) {
  auto tree = parse_csg_json(text);
  if (!tree) return tree.error();
  return CsgSolid::prepare(*tree);
}

Location at(std::string_view text, Vec3 p) {
  auto solid = solid_of(text);
  EXPECT_TRUE(solid.ok()) << solid.error().what();
  return solid ? solid->locate(p) : Location::outside;
}

std::string error_of(std::string_view text) {
  auto tree = parse_csg_json(text, {.source = "scene.json"});
  EXPECT_FALSE(tree.ok());
  return tree ? "" : tree.error().what();
}

TEST(CsgJson, ReadsEveryLeafAndOperationOfTheContract) {
  const char* text = R"({"union": [
      {"sphere": {"center": [0, 0, 0], "radius": 5}},
      {"difference": [{"box": {"min": [10, 0, 0], "max": [12, 2, 2]}},
                      {"halfspace": [1, 0, 0, -11]}]},
      {"intersection": [{"convex": [[1, 0, 0, 20], [-1, 0, 0, -19], [0, 1, 0, 0], [0, -1, 0, 1],
                                    [0, 0, 1, 0], [0, 0, -1, 1]]},
                        {"complement": {"implicit": "0.01 - (x+19.5)^2 - y^2 - z^2"}}]}]})";
  EXPECT_EQ(at(text, {3, 4, 0}), Location::boundary);
  EXPECT_EQ(at(text, {0, 0, 0}), Location::inside);
  EXPECT_EQ(at(text, {10.5, 1, 1}), Location::inside);
  EXPECT_EQ(at(text, {11.5, 1, 1}), Location::outside);  // x >= 11 removed
  EXPECT_EQ(at(text, {-19.2, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(at(text, {-19.5, 0.5, 0.5}), Location::inside);  // outside the removed tiny ball
  EXPECT_EQ(at(text, {-19.5, 0.05, 0.05}), Location::outside);
}

TEST(CsgJson, ImplicitExpressionUsesCaretForPowers) {
  const char* ball = R"({"implicit": "1 - x^2 - y^2 - z^2"})";
  EXPECT_EQ(at(ball, {0, 0, 0}), Location::inside);
  EXPECT_EQ(at(ball, {0, 0, 2}), Location::outside);
  EXPECT_EQ(at(ball, {0, 0, 1}), Location::boundary);
}

TEST(CsgJson, ImplicitLeavesGiveTheSameAnswersOnAnyNumberOfThreads) {
  auto solid = solid_of(R"({"intersection": [{"implicit": "4 - x^2 - y^2 - z^2"},
                                              {"implicit": "sin(3*x) + y"}]})");
  ASSERT_TRUE(solid.ok());
  std::vector<Vec3> points;
  for (int i = 0; i < 20000; ++i)
    points.push_back({(i % 41) / 10.0 - 2, (i % 37) / 9.0 - 2, (i % 13) / 6.0 - 1});
  std::vector<Location> one(points.size()), four(points.size());
  solid->locate(points, one, {.threads = 1});
  solid->locate(points, four, {.threads = 4});
  EXPECT_EQ(one, four);
}

TEST(CsgJson, ErrorsNameTheJsonPathOfTheOffendingValue) {
  EXPECT_EQ(error_of(R"({"union": [{"box": {"min": [0,0,0], "max": [1,1,1]}},
                                   {"sphere": {"center": [0,0,0], "radius": "big"}}]})"),
            "scene.json: union[1].sphere.radius: expected a number, got a string");
  EXPECT_EQ(error_of(R"({"sphere": {"center": [0,0], "radius": 1}})"),
            "scene.json: sphere.center: expected 3 numbers, got 2");
  EXPECT_EQ(error_of(R"({"sphere": {"center": [0,0,0], "radius": -1}})"),
            "scene.json: sphere.radius: expected a radius >= 0");
  EXPECT_EQ(error_of(R"({"box": {"min": [0,2,0], "max": [1,1,1]}})"),
            "scene.json: box: min exceeds max");
  EXPECT_EQ(error_of(R"({"difference": [{"halfspace": [0,0,0,1]}, {"halfspace": [1,0,0,0]}]})"),
            "scene.json: difference[0].halfspace: the normal (a, b, c) is zero");
  EXPECT_EQ(error_of(R"({"convex": [[1,0,0,0], [0,1,0]]})"),
            "scene.json: convex[1]: expected 4 numbers, got 3");
  EXPECT_EQ(error_of(R"({"difference": [{"halfspace": [1,0,0,0]}]})"),
            "scene.json: difference: expected an array of 2 operands, got 1");
  EXPECT_EQ(error_of(R"({"union": []})"), "scene.json: union: expected at least one operand");
}

TEST(CsgJson, RejectsUnknownKeysAndObjectsWithSeveralKeys) {
  EXPECT_NE(
      error_of(R"({"spere": {"center": [0,0,0], "radius": 1}})").find("unknown key \"spere\""),
      std::string::npos);
  EXPECT_EQ(error_of(R"({"sphere": {"center": [0,0,0], "radius": 1, "colour": 3}})"),
            "scene.json: sphere: unknown key \"colour\"");
  EXPECT_EQ(error_of(R"({"complement": {"box": {"min": [0,0,0]}}})"),
            "scene.json: complement.box: missing key \"max\"");
  EXPECT_EQ(error_of(R"({"sphere": {"center": [0,0,0], "radius": 1}, "box": {}})"),
            "scene.json: expected an object with exactly one key, got 2");
}

TEST(CsgJson, RejectsNumbersOutsideTheDoubleRange) {
  auto tree = parse_csg_json(R"({"halfspace": [1, 0, 0, 1e999]})", {.source = "scene.json"});
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::invalid_value);
  EXPECT_EQ(tree.error().what(), "scene.json: number overflow parsing '1e999'");
}

TEST(CsgJson, MalformedJsonReportsTheLine) {
  auto tree = parse_csg_json(
      "{\"union\": [\n  {\"sphere\": {\"center\": [0,0,0], \"radius\": 1}}\n  oops\n]}",
      {.source = "bad.json"});
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::parse);
  EXPECT_EQ(tree.error().source, "bad.json");
  EXPECT_EQ(tree.error().line, 3);
  EXPECT_NE(tree.error().message.find("syntax error"), std::string::npos);
}

TEST(CsgJson, MuparserSyntaxErrorsCarryItsMessage) {
  auto tree = parse_csg_json(R"({"union": [{"implicit": "1 - x^2 -"}]})", {.source = "s.json"});
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::parse);
  EXPECT_EQ(tree.error().message.rfind("union[0].implicit: ", 0), 0u) << tree.error().message;
  auto unknown = parse_csg_json(R"({"implicit": "1 - w"})");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().message.find("\"1 - w\""), std::string::npos)
      << unknown.error().message;
}

// A unit cube, faces as quads (the reader fan-triangulates them).
constexpr const char* kCubeObj = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

// A fresh directory holding scene.json and the given mesh files.
std::filesystem::path scene_dir(const char* name, const std::string& json,
                                std::initializer_list<std::pair<const char*, std::string>> files) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "parts");
  std::ofstream(dir / "scene.json") << json;
  for (const auto& [file, text] : files)
    std::ofstream(dir / file) << text;
  return dir;
}

TEST(CsgJson, MeshLeafIsReadRelativeToTheJsonFile) {
  const auto dir = scene_dir(
      "contain_csg_json_mesh_ok",
      R"({"union": [{"mesh": "parts/cube.obj"}, {"box": {"min": [1,0,0], "max": [2,1,1]}}]})",
      {{"parts/cube.obj", kCubeObj}});
  auto tree = read_csg_json(dir / "scene.json");
  ASSERT_TRUE(tree.ok()) << tree.error().what();
  auto solid = CsgSolid::prepare(*tree);
  ASSERT_TRUE(solid.ok()) << solid.error().what();
  EXPECT_EQ(solid->locate({0.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(solid->locate({1, 0.5, 0.5}), Location::inside);  // the shared face
  EXPECT_EQ(solid->locate({0, 0.5, 0.5}), Location::boundary);
  EXPECT_EQ(solid->locate({-1, 0.5, 0.5}), Location::outside);
  std::filesystem::remove_all(dir);
}

TEST(CsgJson, MissingMeshFileIsAnIoErrorNamingTheLeafAndTheFile) {
  const auto dir = scene_dir(
      "contain_csg_json_mesh_missing",
      R"({"difference": [{"box": {"min": [0,0,0], "max": [1,1,1]}}, {"mesh": "part.obj"}]})", {});
  const auto file = dir / "scene.json";
  auto tree = read_csg_json(file);
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::io);
  EXPECT_EQ(tree.error().source, file.string());
  EXPECT_NE(tree.error().message.find((dir / "part.obj").string()), std::string::npos);
  EXPECT_EQ(tree.error().message.rfind("difference[1].mesh: ", 0), 0u);
  std::filesystem::remove_all(dir);
}

TEST(CsgJson, OpenMeshLeafIsDegenerateNamingTheLeafAndTheFile) {
  std::string open = kCubeObj;
  open.resize(open.rfind("f 4 1 5 8"));  // without its last face
  const auto dir = scene_dir("contain_csg_json_mesh_open",
                             R"({"complement": {"mesh": "open.obj"}})", {{"open.obj", open}});
  auto tree = read_csg_json(dir / "scene.json");
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::degenerate);
  EXPECT_EQ(tree.error().message.rfind("complement.mesh: ", 0), 0u) << tree.error().message;
  EXPECT_NE(tree.error().message.find("open.obj"), std::string::npos);
  EXPECT_NE(tree.error().message.find("not closed"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CsgJson, UnreadableMeshKeepsTheMeshReadersKindAndLine) {
  const auto dir = scene_dir("contain_csg_json_mesh_bad", R"({"mesh": "bad.obj"})",
                             {{"bad.obj", "v 0 0 0\nv 1 0 zero\n"}});
  auto tree = read_csg_json(dir / "scene.json");
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::parse);
  EXPECT_NE(tree.error().message.find("bad.obj:2"), std::string::npos) << tree.error().message;
  std::filesystem::remove_all(dir);
}

TEST(CsgJson, MissingFileIsAnIoError) {
  auto tree = read_csg_json("/nonexistent/contain/scene.json");
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::io);
}

// Regression (found by fuzz/fuzz_csg_json's bad-input row "deep nesting"): 10^5 nested
// complements overflowed the stack of the recursive reader (SIGSEGV in `contain inside --csg`).
TEST(CsgJson, DeeplyNestedTreeIsRefusedInsteadOfOverflowingTheStack) {
  const int depth = 100000;
  std::string text;
  for (int i = 0; i < depth; ++i)
    text += "{\"complement\": ";
  text += R"({"sphere": {"center": [0, 0, 0], "radius": 1}})";
  text.append(static_cast<std::size_t>(depth), '}');
  auto tree = parse_csg_json(text, {.source = "deep.json"});
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.error().kind, ErrorKind::unsupported);
  EXPECT_NE(tree.error().what().find("nested more than 256 levels"), std::string::npos);
}

TEST(CsgJson, TreesUpToTheDepthLimitAreRead) {
  std::string text;
  for (int i = 0; i < 254; ++i)
    text += "{\"complement\": ";
  text += R"({"sphere": {"center": [0, 0, 0], "radius": 1}})";
  text.append(254, '}');
  EXPECT_EQ(at(text, {0, 0, 0}), Location::inside);  // an even number of complements
}

// nlohmann-json keeps the last of two equal names: a second "op"-like member would silently
// change the tree, so a name given twice is bad input naming it.
TEST(CsgJson, AMemberGivenTwiceIsBadInputNamingIt) {
  const std::string message =
      error_of(R"({"sphere": {"center": [0, 0, 0], "radius": 5, "radius": 50}})");
  EXPECT_NE(message.find("\"radius\" is given twice"), std::string::npos) << message;
  EXPECT_NE(message.find("scene.json"), std::string::npos) << message;
  // The same name in two objects is no repeat.
  EXPECT_EQ(at(R"({"union": [{"sphere": {"center": [0, 0, 0], "radius": 1}},
                             {"sphere": {"center": [5, 0, 0], "radius": 1}}]})",
               {5, 0, 0}),
            Location::inside);
}

}  // namespace
}  // namespace contain::io
