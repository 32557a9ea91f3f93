#include "contain/io/scene_json.h"

#include <gtest/gtest.h>

#include <string>

namespace contain::io {
namespace {

// A misspelt member would be dropped in silence (issue 24: "transfrom" left an object unmoved,
// and two cubes 5 apart were reported as intersecting): every member must be one the reader
// knows, and the error names the member, its object and its line.
TEST(SceneJson, AnUnknownMemberOfAnObjectIsBadInputNamingItAndTheObject) {
  const auto scene = parse_scene_json(R"({"objects": [
    {"id": "a", "mesh": "cube.off", "transfrom": [1,0,0,5, 0,1,0,0, 0,0,1,0]}]})",
                                      {.source = "s.json"});
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(scene.error().message.find("objects[0]"), std::string::npos) << scene.error().message;
  EXPECT_NE(scene.error().message.find("\"transfrom\""), std::string::npos);
  EXPECT_NE(scene.error().message.find("\"transform\""), std::string::npos);  // the known ones
  EXPECT_EQ(scene.error().line, 2);
  EXPECT_EQ(scene.error().source, "s.json");
}

TEST(SceneJson, AnUnknownMemberOfTheRootIsBadInput) {
  const auto scene = parse_scene_json(R"({"objects": [], "object": []})");
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(scene.error().message.find("the scene: unknown member \"object\""), std::string::npos)
      << scene.error().message;
  // The known members alone read.
  EXPECT_TRUE(parse_scene_json(R"({"objects": []})"));
}

// JSON leaves it to the reader which of two equal names counts: a second "mesh" or "transform"
// would silently win, so a name given twice is bad input naming it and its line.
TEST(SceneJson, AMemberGivenTwiceIsBadInputNamingItAndItsLine) {
  const auto scene = parse_scene_json(R"({"objects": [
    {"id": "a", "mesh": "cube.off",
     "mesh": "other.off"}]})",
                                      {.source = "s.json"});
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().kind, ErrorKind::parse);
  EXPECT_NE(scene.error().message.find("\"mesh\" is given twice"), std::string::npos)
      << scene.error().message;
  EXPECT_EQ(scene.error().line, 3);
  // Equal names in different objects are not repeats.
  EXPECT_TRUE(parse_scene_json(R"({"objects": []})"));
}

// Objects of many members look names up in a set (past 32 of them): the repeat is found there too.
TEST(SceneJson, ARepeatAmongManyMembersIsFoundToo) {
  std::string text = R"({"objects": [], "x": {)";
  for (int k = 0; k < 100; ++k)
    text += "\"m" + std::to_string(k) + "\": " + std::to_string(k) + ", ";
  const auto scene = parse_scene_json(text + R"("m77": 0}})");
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("\"m77\" is given twice"), std::string::npos)
      << scene.error().message;
}

}  // namespace
}  // namespace contain::io
