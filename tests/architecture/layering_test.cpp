// The layering of docs/architecture.md, enforced: the checker on small trees made up here (it
// must catch each kind of violation), then on the project's own tree (it must find none).

#include "architecture/layering.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "architecture/project_tree.h"

namespace contain::test {
namespace {

const LayerOrder kOrder = parse_layer_order(
    "core -> values -> predicates -> shapes -> bvh, bound -> inside -> clip, collide -> io -> cli");

std::vector<std::string> check(std::vector<SourceFile> files) {
  return check_layering(kOrder, files);
}

TEST(Layering, OrderParsesLevelsAndSiblings) {
  ASSERT_EQ(kOrder.levels.size(), 9u);
  EXPECT_EQ(kOrder.level_of("core"), 0);
  EXPECT_EQ(kOrder.level_of("bvh"), kOrder.level_of("bound"));
  EXPECT_LT(kOrder.level_of("shapes"), kOrder.level_of("inside"));
  EXPECT_EQ(kOrder.level_of("nowhere"), -1);
}

TEST(Layering, OrderIsReadFromTheLineAfterTheMarker) {
  const LayerOrder order =
      layer_order_from_doc("# Title\n<!-- layer-order -->\n```text\na -> b, c -> d\n```\n");
  ASSERT_EQ(order.levels.size(), 3u);
  EXPECT_EQ(order.levels[1], (std::vector<std::string>{"b", "c"}));
  EXPECT_TRUE(layer_order_from_doc("no marker here").levels.empty());
}

TEST(Layering, IncludesOfLowerPublicHeadersAndOwnPrivateOnesPass) {
  EXPECT_TRUE(check({{"src/inside/a.cpp",
                      "#include \"contain/inside/a.h\"\n#include \"contain/shapes/polygon.h\"\n"
                      "#include \"inside/kernel.h\"\n#include \"local.h\"\n#include <vector>\n"},
                     {"include/contain/shapes/p.h",
                      "#include \"contain/values/vec.h\"\nnamespace contain::shapes {\n"
                      "values::Vec2 f(predicates::BigFloat);\n}\n"}})
                  .empty());
}

TEST(Layering, IncludeOfAHigherLayerIsReported) {
  const auto problems = check(
      {{"include/contain/values/v.h", "#pragma once\n#include \"contain/shapes/polygon.h\"\n"}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("include/contain/values/v.h:2: includes contain/shapes/polygon.h"),
            std::string::npos)
      << problems[0];
  EXPECT_NE(problems[0].find("a higher layer"), std::string::npos);
}

TEST(Layering, IncludeOfASiblingLayerIsReported) {
  const auto problems = check({{"src/bvh/b.cpp", "#include <contain/bound/aabb.h>\n"}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("a sibling layer"), std::string::npos) << problems[0];
}

TEST(Layering, IncludeOfAnotherDomainsPrivateHeaderIsReported) {
  const auto problems = check({{"src/clip/exact.h", "#include \"predicates/big_float.h\"\n"},
                               {"src/collide/m.cpp", "#include \"inside/mesh_ray.h\"\n"}});
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("a private header of predicates"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("a private header of inside"), std::string::npos) << problems[1];
}

TEST(Layering, HigherNamespaceInALowerPublicHeaderIsReported) {
  const auto problems =
      check({{"include/contain/predicates/p.h",
              "namespace contain::predicates {\nSign f(const shapes::Polygon& p);\n}\n"}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("p.h:2: names shapes::"), std::string::npos) << problems[0];
}

TEST(Layering, NamesInCommentsAndStringsAndSourcesAreNotUses) {
  EXPECT_TRUE(
      check({{"include/contain/shapes/c.h",
              "/// located by inside::CsgSolid\n/* io::read */\nconst char* s = \"clip::x\";\n"
              "// #include \"contain/io/wkt.h\"\n"},
             {"src/shapes/c.cpp", "// inside::CsgSolid\nint x = inside::y;\n"}})
          .empty());
}

TEST(Layering, CommentedOutIncludeIsNotAnInclude) {
  EXPECT_TRUE(check({{"src/values/a.cpp", "/*\n#include \"contain/io/wkt.h\"\n*/\n"}}).empty());
}

TEST(Layering, FolderMissingFromTheOrderIsReported) {
  const auto problems = check({{"src/geometry/polygon.cpp", "\n"}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("'geometry' is not in the layer order"), std::string::npos);
}

TEST(Layering, LinkingAHigherOrSiblingLibraryIsReported) {
  const auto problems = check_link_order(
      kOrder,
      {{"src/shapes/CMakeLists.txt",
        "contain_library(shapes SOURCES a.cpp DEPS contain_predicates)"},
       {"src/bvh/CMakeLists.txt", "contain_library(bvh SOURCES a.cpp DEPS contain_bound)"},
       {"src/values/CMakeLists.txt", "contain_library(values SOURCES a.cpp DEPS contain_inside)"}});
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("links contain_bound, a sibling layer of bvh"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[1].find("links contain_inside, a higher layer of values"), std::string::npos)
      << problems[1];
}

// The project itself.

LayerOrder project_order() {
  return layer_order_from_doc(read(kRoot / "docs/architecture.md"));
}

TEST(Layering, ProjectOrderNamesEveryLibraryFolder) {
  const LayerOrder order = project_order();
  ASSERT_FALSE(order.levels.empty()) << "no <!-- layer-order --> line in docs/architecture.md";
  for (const auto& entry : std::filesystem::directory_iterator(kRoot / "src")) {
    if (entry.is_directory()) {
      EXPECT_GE(order.level_of(entry.path().filename().string()), 0) << entry.path();
    }
  }
}

TEST(Layering, ProjectFilesUseOnlyLowerLayersAndTheirPublicHeaders) {
  const auto files = tree({"include", "src", "cli", "python/src", "scenes"}, false);
  ASSERT_GT(files.size(), 100u);
  const auto problems = check_layering(project_order(), files);
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

TEST(Layering, ProjectLibrariesLinkOnlyLowerLayers) {
  const auto problems = check_link_order(project_order(), tree({"src"}, true));
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

}  // namespace
}  // namespace contain::test
