// tests/data/io: files the readers must refuse with a clear error (NaN, bad numbers, indices out of
// range, counts beyond the file, nesting past 256 levels) or read at once (an element without
// properties claiming 10^12 rows), and a WKB ring that must survive the writer; checked through
// the library's readers and writers and through the command.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "contain/io/csg_json.h"
#include "contain/io/layer_io.h"
#include "contain/io/mesh_io.h"
#include "contain/io/points_io.h"
#include "contain/io/region_io.h"
#include "contain/io/scene_json.h"
#include "contain/io/wkb.h"
#include "contain/io/wkt.h"
#include "regression/regression_corpus.h"

namespace contain::test {
namespace {

// Reads every file the command names with the reader the command uses; "" when all read, else the
// first error as the command words it ("source:line: message").
std::string first_reader_error(const RegressionCase& c) {
  const bool plane = c.option("--polygon").has_value() || c.option("--layer").has_value();
  if (const auto f = c.option("--polygon")) {
    if (auto r = io::read_region(*f); !r.ok()) return r.error().what();
  }
  if (const auto f = c.option("--mesh")) {
    if (auto r = io::read_mesh(*f); !r.ok()) return r.error().what();
  }
  if (const auto f = c.option("--csg")) {
    if (auto r = io::read_csg_json(*f); !r.ok()) return r.error().what();
  }
  if (const auto f = c.option("--scene")) {
    if (auto r = io::read_scene_json(*f); !r.ok()) return r.error().what();
  }
  if (const auto f = c.option("--layer")) {
    if (auto r = io::read_layer(*f, {.id = c.option("--id").value_or("")}); !r.ok()) {
      return r.error().what();
    }
  }
  if (const auto f = c.option("--points")) {
    if (plane) {
      if (auto r = io::read_points2(*f); !r.ok()) return r.error().what();
    } else if (auto r = io::read_points3(*f); !r.ok()) {
      return r.error().what();
    }
  }
  return "";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `lib wkb-roundtrip FILE`: the region read from FILE is written as WKT exactly as recorded, and
// survives format_wkb / parse_wkb unchanged (commit 1b818be).
void expect_wkb_roundtrip(const RegressionCase& c) {
  auto region = io::parse_wkb(slurp(c.lib[1]), c.lib[1]);
  ASSERT_TRUE(region.ok()) << region.error().what();
  EXPECT_EQ(std::vector<std::string>{io::format_wkt(*region)}, c.out);
  auto back = io::parse_wkb(io::format_wkb(*region), "written");
  ASSERT_TRUE(back.ok()) << back.error().what();
  EXPECT_EQ(*back, *region);
}

TEST(RegressionCorpus, IoCasesGiveTheirRecordedResultsThroughTheLibrary) {
  const auto cases = read_regression_cases("io");
  ASSERT_FALSE(cases.empty());
  for (const RegressionCase& c : cases) {
    SCOPED_TRACE("case " + c.name + " (cases.txt:" + std::to_string(c.line) + ")");
    if (!c.lib.empty()) {
      ASSERT_EQ(c.lib.size(), 2u);
      ASSERT_EQ(c.lib[0], "wkb-roundtrip") << "unknown library check";
      expect_wkb_roundtrip(c);
      continue;
    }
    const std::string error = first_reader_error(c);
    if (c.exit_code == 0) {
      EXPECT_EQ(error, "");
      continue;
    }
    EXPECT_EQ(c.exit_code, 3) << "bad input is exit 3";
    ASSERT_NE(error, "") << "every reader accepted the files";
    for (const std::string& fragment : c.err) {
      EXPECT_NE(error.find(fragment), std::string::npos) << error << "\nlacks: " << fragment;
    }
  }
}

TEST(RegressionCorpus, IoCasesGiveTheirRecordedResultsThroughTheCommand) {
  for (const RegressionCase& c : read_regression_cases("io")) {
    if (!c.run.empty()) expect_cli_gives_recorded_answer(c);
  }
}

TEST(RegressionCorpus, EveryIoFileHasACase) {
  expect_every_file_has_a_case("io", read_regression_cases("io"));
}

}  // namespace
}  // namespace contain::test
