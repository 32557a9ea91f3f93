// contain collide, continuous collision, end to end (../shared/spec/cli.md, "Continuous
// collision"): primitive queries from the benchmark's CSV and from 24-number files, moving meshes
// by placements and by a motions file, JSON witnesses.

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run.h"
#include "contain/collide/ccd.h"
#include "contain/io/ccd_queries.h"
#include "support/case_budget.h"
#include "support/shared_corpus.h"

namespace contain::test {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

TEST(CollideCcdCli, EveryCorpusFileGivesTheExpectedAnswersAndTheLibrarysTimes) {
  CONTAIN_REQUIRE_SHARED();
  int files = 0, queries = 0;
  for (const auto& scene : std::filesystem::directory_iterator(*shared_dir() / "corpus/ccd")) {
    if (!scene.is_directory()) continue;
    for (const char* kind : {"vertex-face", "edge-edge"}) {
      for (const auto& file : std::filesystem::directory_iterator(scene.path() / kind)) {
        // Unoptimised sanitizer builds run one file of each kind per scene (the release build
        // runs all 24; the library itself runs all of them in CcdCorpus under the sanitizers).
        if (test::reduced_cases && file.path().filename() != "data_0_0.csv") continue;
        const CliRun run = run_contain(
            {"collide", "--ccd", kind, "--queries", file.path().string(), "--threads", "2"});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const auto read = io::read_ccd_queries(file.path());
        ASSERT_TRUE(read.ok());
        const std::vector<std::string> got = lines(run.out);
        ASSERT_EQ(got.size(), read->queries.size()) << file.path();
        for (std::size_t i = 0; i < got.size(); ++i) {
          const collide::Impact expected = std::string(kind) == "vertex-face"
                                               ? collide::vertex_face_ccd(read->queries[i])
                                               : collide::edge_edge_ccd(read->queries[i]);
          EXPECT_EQ(expected.hit, read->expected[i] == 1);
          EXPECT_EQ(got[i], expected.hit ? fmt::format("hit {}", expected.time) : "miss")
              << file.path() << " query " << i;
        }
        ++files;
        queries += static_cast<int>(got.size());
      }
    }
  }
  if (test::reduced_cases) {
    EXPECT_EQ(files, 12);
    EXPECT_GT(queries, 1000);
  } else {
    EXPECT_EQ(files, 24);
    EXPECT_EQ(queries, 2824);
  }
}

TEST(CollideCcdCli, NumbersFormatIsOneQueryALineAndJsonNamesTheStage) {
  const TempDir dir;
  const std::string file =
      dir.write("q.txt",
                "# vertex through the triangle at t = 1/2, then beside it\n"
                "0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0\n"
                "2,2,1, 0,0,0, 1,0,0, 0,1,0, 2,2,-1, 0,0,0, 1,0,0, 0,1,0\n");
  CliRun run = run_contain({"collide", "--ccd", "vertex-face", "--queries", file});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "hit 0.5\nmiss\n");
  run = run_contain({"collide", "--ccd", "vertex-face", "--queries", file, "--json"});
  EXPECT_EQ(run.out,
            "{\"hit\":true,\"time\":0.5,\"stage\":\"filter\"}\n"
            "{\"hit\":false,\"time\":null,\"stage\":\"boxes\"}\n");
  run = run_contain({"collide", "--ccd", "vertex-face", "--queries", "-"},
                    "0.25 0.25 0 0 0 0 1 0 0 0 1 0 0.25 0.25 0 0 0 0 1 0 0 0 1 0\n");
  EXPECT_EQ(run.out, "hit 0\n");
  const std::string out = (dir.path() / "out.txt").string();
  run = run_contain({"collide", "--ccd", "edge-edge", "--queries", file, "--out", out, "--quiet"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "");
}

const char* kBox =
    "OFF\n8 12 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
    "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n"
    "3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n";

TEST(CollideCcdCli, FastBulletThroughAThinPlateIsHitBetweenDisjointPoses) {
  const TempDir dir;
  const std::string box = dir.write("box.off", kBox);
  // The plate: the box scaled to 2 x 2 x 0.02; the bullet: 0.1 x 0.1 x 0.1 from z = 3 to z = -3.
  const std::string plate = "1,0,0,0,0,1,0,0,0,0,0.01,0";
  const std::string from = "0.05,0,0,0.1,0,0.05,0,0.2,0,0,0.05,3";
  const std::string to = "0.05,0,0,0.1,0,0.05,0,0.2,0,0,0.05,-3";
  CliRun run = run_contain({"collide", box, box, "--transform-a", plate, "--transform-b", from});
  EXPECT_EQ(run.out, "disjoint\n");
  run = run_contain({"collide", box, box, "--transform-a", plate, "--transform-b", to});
  EXPECT_EQ(run.out, "disjoint\n");
  run = run_contain({"collide", box, box, "--transform-a", plate, "--from-b", from, "--to-b", to});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "hit 0.49\n");
  run = run_contain(
      {"collide", box, box, "--transform-a", plate, "--from-b", from, "--to-b", to, "--json"});
  EXPECT_NE(run.out.find("{\"hit\":true,\"time\":0.49,\"witness\":{\"kind\":\""), std::string::npos)
      << run.out;
  // A moving too: it rises to meet the bullet earlier.
  run = run_contain({"collide", box, box, "--from-a", plate, "--to-a", "1,0,0,0,0,1,0,0,0,0,0.01,2",
                     "--from-b", from, "--to-b", to});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.out.substr(0, 4), "hit ");
  EXPECT_LT(std::stod(run.out.substr(4)), 0.49);
}

TEST(CollideCcdCli, MotionsFileGivesOneAnswerPerMotion) {
  const TempDir dir;
  const std::string box = dir.write("box.off", kBox);
  const std::string motions = dir.write("motions.txt",
                                        "# B from x = 5 to x = 1: touches at t = 3/4\n"
                                        "1 0 0 5 0 1 0 0 0 0 1 0   1 0 0 1 0 1 0 0 0 0 1 0\n"
                                        "# B from x = 5 to x = 3: never touches\n"
                                        "1,0,0,5,0,1,0,0,0,0,1,0, 1,0,0,3,0,1,0,0,0,0,1,0\n"
                                        "# overlapping at t = 0\n"
                                        "1 0 0 1 0 1 0 0 0 0 1 0   1 0 0 9 0 1 0 0 0 0 1 0\n");
  CliRun run = run_contain({"collide", box, box, "--motions", motions});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "hit 0.75\nmiss\nhit 0\n");
  run = run_contain({"collide", box, box, "--motions", motions, "--json", "--threads", "1"});
  const std::vector<std::string> got = lines(run.out);
  ASSERT_EQ(got.size(), 3U);
  EXPECT_NE(got[1].find("\"hit\":false,\"time\":null,\"witness\":null"), std::string::npos);
  EXPECT_NE(got[2].find("\"witness\":{\"kind\":\"initial\""), std::string::npos);
}

TEST(CollideCcdCli, UsageErrorsAreExitTwo) {
  const TempDir dir;
  const std::string box = dir.write("box.off", kBox);
  const std::string region = dir.write("r.wkt", "POLYGON((0 0, 1 0, 0 1, 0 0))");
  EXPECT_EQ(run_contain({"collide", "--ccd", "vertex-face"}).exit_code, 2);
  EXPECT_EQ(run_contain({"collide", "--ccd", "face-face", "--queries", box}).exit_code, 2);
  EXPECT_EQ(run_contain({"collide", box, box, "--ccd", "edge-edge", "--queries", box}).exit_code,
            2);
  EXPECT_EQ(run_contain({"collide", box, box, "--from-b", "1,0,0,0,0,1,0,0,0,0,1,0"}).exit_code, 2);
  EXPECT_EQ(run_contain({"collide", box, box, "--from-b", "1,0,0", "--to-b", "1,0,0"}).exit_code,
            2);
  EXPECT_EQ(run_contain({"collide", region, region, "--from-b", "1,0,0,0,0,1,0,0,0,0,1,0", "--to-b",
                         "1,0,0,0,0,1,0,0,0,0,1,0"})
                .exit_code,
            2);
  EXPECT_EQ(run_contain({"collide", box}).exit_code, 2);
}

}  // namespace
}  // namespace contain::test
