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

}  // namespace
}  // namespace contain::io
