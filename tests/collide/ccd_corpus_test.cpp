// Every query of the shared CCD corpus (../shared/corpus/ccd: sample queries of the benchmark of
// Wang et al. 2021 with exact answers): no false and no missed contact, and every time of
// contact equal to the GMP oracle's rounded-down earliest time.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "collide/ccd_oracle.h"
#include "contain/collide/ccd.h"
#include "contain/io/ccd_queries.h"
#include "support/shared_corpus.h"

namespace contain::collide {
namespace {

struct Scene {
  std::string name;
  io::CcdQueries vertex_face, edge_edge;
};

std::vector<Scene> read_corpus() {
  std::vector<Scene> scenes;
  const std::filesystem::path root = *test::shared_dir() / "corpus/ccd";
  for (const auto& entry : std::filesystem::directory_iterator(root)) {
    if (!entry.is_directory()) continue;
    Scene s{entry.path().filename().string(), {}, {}};
    for (auto [kind, into] :
         {std::pair{"vertex-face", &s.vertex_face}, std::pair{"edge-edge", &s.edge_edge}}) {
      std::vector<std::filesystem::path> files;
      for (const auto& f : std::filesystem::directory_iterator(entry.path() / kind))
        files.push_back(f.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        auto q = io::read_ccd_queries(f);
        EXPECT_TRUE(q.ok()) << (q.ok() ? "" : q.error().what());
        if (!q) continue;
        into->queries.insert(into->queries.end(), q->queries.begin(), q->queries.end());
        into->expected.insert(into->expected.end(), q->expected.begin(), q->expected.end());
        into->lines.insert(into->lines.end(), q->lines.begin(), q->lines.end());
      }
    }
    scenes.push_back(std::move(s));
  }
  std::sort(scenes.begin(), scenes.end(),
            [](const Scene& a, const Scene& b) { return a.name < b.name; });
  return scenes;
}

template <class Library, class Oracle>
void check_all(const std::string& scene, const char* kind, const io::CcdQueries& set, Library lib,
               Oracle oracle) {
  int false_hits = 0, missed = 0, wrong_time = 0, hits = 0;
  for (std::size_t i = 0; i < set.queries.size(); ++i) {
    const Impact got = lib(set.queries[i]);
    const bool truth = set.expected[i] == 1;
    hits += truth ? 1 : 0;
    if (got.hit && !truth) ++false_hits;
    if (!got.hit && truth) ++missed;
    if (got.hit != truth) {
      ADD_FAILURE() << scene << " " << kind << " query " << i << " (line " << set.lines[i]
                    << "): got " << (got.hit ? "hit" : "miss") << ", expected "
                    << (truth ? "hit" : "miss");
      continue;
    }
    if (got.hit) {
      const std::optional<double> t = oracle(set.queries[i]);
      if (!t || *t != got.time) {
        ++wrong_time;
        ADD_FAILURE() << scene << " " << kind << " query " << i << ": time " << got.time
                      << ", oracle " << (t ? *t : -1.0);
      }
    }
  }
  EXPECT_EQ(false_hits, 0);
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(wrong_time, 0);
  std::printf("%-28s %-12s %4zu queries, %4d hits: %d false, %d missed, %d wrong times\n",
              scene.c_str(), kind, set.queries.size(), hits, false_hits, missed, wrong_time);
}

TEST(CcdCorpus, EveryQueryOfEverySceneIsExact) {
  CONTAIN_REQUIRE_SHARED();
  const std::vector<Scene> scenes = read_corpus();
  ASSERT_EQ(scenes.size(), 6U);
  std::size_t total = 0;
  for (const Scene& s : scenes) {
    check_all(
        s.name, "vertex-face", s.vertex_face, [](const CcdQuery& q) { return vertex_face_ccd(q); },
        test::exact_vertex_face_time);
    check_all(
        s.name, "edge-edge", s.edge_edge, [](const CcdQuery& q) { return edge_edge_ccd(q); },
        test::exact_edge_edge_time);
    total += s.vertex_face.queries.size() + s.edge_edge.queries.size();
  }
  EXPECT_EQ(total, 2824U);
}

TEST(CcdCorpus, TheOracleAgreesWithTheBenchmarksAnswers) {
  CONTAIN_REQUIRE_SHARED();
  for (const Scene& s : read_corpus()) {
    for (auto [set, oracle] : {std::pair{&s.vertex_face, &test::exact_vertex_face_time},
                               std::pair{&s.edge_edge, &test::exact_edge_edge_time}}) {
      for (std::size_t i = 0; i < set->queries.size(); ++i) {
        EXPECT_EQ(oracle(set->queries[i]).has_value(), set->expected[i] == 1)
            << s.name << " query " << i << " line " << set->lines[i];
      }
    }
  }
}

}  // namespace
}  // namespace contain::collide
