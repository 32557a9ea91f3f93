// The check of the written mesh restricted to the triangles with a corner that is not kept gives
// the full check's answer, and both give the GMP oracle's (invalid_reason: exact areas,
// collide::self_intersections), on valid results of the engine whose vertices are then moved:
// by an ulp, by 1e-14, by rounding-sized steps and by large ones that cross or flip triangles,
// with the moved vertices marked not kept (the others are still the exact arrangement's).

#include "clip/solid/validate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/solid_oracle.h"
#include "contain/clip/mesh_boolean.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::Op;
using clip::solid::check_written;

Mesh boolean(const std::vector<Mesh>& inputs, Op op) {
  const Result<clip::MeshBooleanResult> r = clip::mesh_boolean(inputs, {.op = op});
  EXPECT_TRUE(r.ok());
  return r.ok() ? r->mesh : Mesh{};
}

// The restricted check, the full check and the oracle agree on `mesh` with `kept`, and the two
// checks name the same triangles of wrongly meeting pairs (the region a snap round repairs);
// returns whether the mesh is valid.
bool agree(const Mesh& mesh, const std::vector<bool>& kept, const std::string& what) {
  const bool restricted = check_written(mesh, kept).ok();
  const bool full = check_written(mesh).ok();
  const std::string reason = invalid_reason(mesh);
  EXPECT_EQ(restricted, full) << what;
  std::vector<std::int32_t> near, all;
  EXPECT_EQ(check_written(mesh, kept, &near).ok(), restricted) << what;
  EXPECT_EQ(check_written(mesh, std::vector<bool>(mesh.vertices.size(), false), &all).ok(), full)
      << what;
  EXPECT_EQ(near, all) << what;
  EXPECT_EQ(full, reason.empty()) << what << ": " << reason;
  return full;
}

// Valid results of the engine with every vertex kept, and with a few vertices moved by
// `step` times a random unit (in every coordinate) and marked not kept; counts the invalid ones.
int moved_cases(const Mesh& valid, double step, int trials, std::mt19937_64& rng,
                const std::string& what) {
  std::vector<bool> kept(valid.vertices.size(), true);
  EXPECT_TRUE(agree(valid, kept, what + " as written"));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, valid.vertices.size() - 1);
  int invalid = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Mesh mesh = valid;
    std::vector<bool> flags = kept;
    for (int k = 0; k < 1 + trial % 3; ++k) {
      const std::size_t v = pick(rng);
      Vec3& p = mesh.vertices[v];
      p = {p.x + step * u(rng), p.y + step * u(rng), p.z + step * u(rng)};
      flags[v] = false;
    }
    invalid += agree(mesh, flags, what + " trial " + std::to_string(trial)) ? 0 : 1;
  }
  return invalid;
}

TEST(CheckWritten, RestrictedAndFullChecksAgreeWithTheOracleOnMovedVertices) {
  std::mt19937_64 rng(5);
  const Mesh sphere = icosphere(1, 1.0, {0, 0, 0});
  const Mesh other = icosphere(1, 0.8, {0.3, 0.2, 0.1});
  // Boxes on a lattice: coplanar faces merged; the xor of boxes touching along an edge and at
  // a corner: sheets kept apart at one position.
  const Mesh a = box_mesh({0, 0, 0}, {2, 2, 2}), b = box_mesh({1, 1, 1}, {3, 3, 3});
  const Mesh edge = box_mesh({2, 2, 0}, {3, 3, 2}), corner = box_mesh({2, 2, 2}, {3, 3, 3});
  const std::vector<std::pair<std::string, Mesh>> valid = {
      {"spheres union", boolean({sphere, other}, Op::union_)},
      {"spheres difference", boolean({sphere, other}, Op::difference)},
      {"boxes union", boolean({a, b}, Op::union_)},
      {"boxes xor", boolean({a, b}, Op::xor_)},
      {"boxes touching along an edge", boolean({a, edge}, Op::union_)},
      {"boxes touching at a corner", boolean({a, corner}, Op::union_)}};
  const int trials = case_budget(8, 4);
  int invalid = 0;
  for (const auto& [what, mesh] : valid) {
    ASSERT_FALSE(mesh.triangles.empty()) << what;
    for (const double step : {1e-16, 1e-14, 1e-3, 0.5})
      invalid += moved_cases(mesh, step, trials, rng, what + " step " + std::to_string(step));
  }
  EXPECT_GT(invalid, 0);  // the large steps do break some: both answers were exercised
}

// The check's pair stage (meeting_pairs: crossings enclosed, not rounded nor stored) makes the
// engine's decisions (intersect_pairs): the same number of constraints in every triangle, the
// same coplanar partners, and the constraints along input edges at the same places; on spheres
// crossing, a sphere against a copy turned by 1e-9 (crossings of nearly parallel planes) and
// boxes sharing faces.
TEST(CheckWritten, MeetingPairsMakeTheDecisionsOfThePairStage) {
  const Mesh sphere = icosphere(2, 1.0, {0, 0, 0});
  Mesh turned = sphere;
  const double c = std::cos(1e-9), s = std::sin(1e-9);
  for (Vec3& v : turned.vertices)
    v = {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
  const std::vector<std::pair<std::string, std::vector<Mesh>>> cases = {
      {"spheres", {sphere, icosphere(2, 0.8, {0.3, 0.2, 0.1})}},
      {"turned by 1e-9", {sphere, turned}},
      {"boxes", {box_mesh({0, 0, 0}, {2, 2, 2}), box_mesh({1, 0, 0}, {3, 2, 2})}}};
  for (const auto& [what, inputs] : cases) {
    const Result<clip::solid::Soup> soup = clip::solid::make_soup(inputs);
    ASSERT_TRUE(soup.ok()) << what;
    clip::solid::PointStore store;
    store.add_vertices(*soup);
    const std::vector<clip::solid::TriangleWork> stored =
        clip::solid::intersect_pairs(*soup, store);
    const std::vector<clip::solid::TriangleWork> met = clip::solid::meeting_pairs(*soup);
    ASSERT_EQ(stored.size(), met.size()) << what;
    std::size_t constraints = 0;
    for (std::size_t t = 0; t < met.size(); ++t) {
      ASSERT_EQ(stored[t].constraints.size(), met[t].constraints.size()) << what << " " << t;
      EXPECT_EQ(stored[t].coplanar, met[t].coplanar) << what << " " << t;
      for (std::size_t i = 0; i < met[t].constraints.size(); ++i)
        EXPECT_EQ(stored[t].constraints[i].edge, met[t].constraints[i].edge) << what;
      constraints += met[t].constraints.size();
    }
    EXPECT_GT(constraints, 0U) << what;
  }
}

// Made by hand: the top vertex of an octahedron pushed down and out past a lower face folds
// its triangles through the lower ones; one moved onto the line of two others makes a
// zero-area triangle; the untouched vertices are kept. The restricted check catches both, as
// the full one. (Pushed straight down through the bottom vertex to (0, 0, -2) instead, the
// mesh turns inside out without any two triangles meeting: no pair test sees that, the
// orientation test of the shells does: InsideOutShells below.) Edges not matched exactly once
// are found whatever is kept.
TEST(CheckWritten, AFoldedAndAZeroAreaTriangleAreFoundFromTheirMovedCornerAndBadEdgesAlways) {
  const Mesh octahedron{
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  std::vector<bool> kept(6, true);
  EXPECT_TRUE(agree(octahedron, kept, "octahedron"));
  Mesh flipped = octahedron;
  flipped.vertices[4] = {0.6, 0.6, -0.3};
  kept[4] = false;
  EXPECT_FALSE(agree(flipped, kept, "flipped"));
  Mesh flat = octahedron;
  flat.vertices[4] = {0.5, 0.5, 0};  // on the segment from vertex 0 to vertex 2
  EXPECT_FALSE(agree(flat, kept, "zero area"));
  EXPECT_EQ(check_written(flat, kept).error().message.find("zero area") == std::string::npos,
            false);
  // Every corner kept: the pairs are not tested (the caller vouches for them), edges and areas
  // still are.
  EXPECT_TRUE(check_written(flipped, std::vector<bool>(6, true)).ok());
  EXPECT_FALSE(check_written(flat, std::vector<bool>(6, true)).ok());
  // One triangle turned over: three directed edges twice, three never reversed. The same
  // triangle twice and its reverse twice: every edge matched, but twice. Both fail, kept or not.
  Mesh turned = octahedron;
  std::swap(turned.triangles[0][1], turned.triangles[0][2]);
  Mesh doubled = octahedron;
  for (int k = 0; k < 2; ++k) {
    doubled.triangles.push_back(octahedron.triangles[0]);
    doubled.triangles.push_back(
        {octahedron.triangles[0][0], octahedron.triangles[0][2], octahedron.triangles[0][1]});
  }
  for (const Mesh* m : {&turned, &doubled}) {
    EXPECT_EQ(check_written(*m, std::vector<bool>(6, true)).error().message.find("edge") ==
                  std::string::npos,
              false);
    EXPECT_FALSE(check_written(*m).ok());
    EXPECT_NE(invalid_reason(*m), "");
  }
}

// Shells whose triangles meet no other triangle can still be inside out: a box reversed, alone
// or beside another box, an octahedron whose top vertex is pushed through its bottom one, two
// boxes nested in one direction (winding number 2 inside both). The check proves orientation
// (exact volume of each shell, and the other shells' side at one of its vertices) whatever is
// kept, as the oracle does; a hollow box (an outward shell around an inward one), three nested
// shells alternating, boxes touching at a corner and a tiny box far from the origin (its volume
// decided with exact numbers: the doubles' sum is all rounding) pass. One shell alone is decided
// by its volume only (no table of the other shells' positions): a reversed box, the pushed
// octahedron and the tiny reversed box are such single shells, checked against the oracle.
TEST(CheckWritten, InsideOutShells) {
  const Mesh unit = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh big = box_mesh({-2, -2, -2}, {3, 3, 3});
  const Mesh huge = box_mesh({-4, -4, -4}, {5, 5, 5});
  const double tiny = std::ldexp(1.0, -30);
  const Mesh far = box_mesh({1e6, 1e6, 1e6}, {1e6 + tiny, 1e6 + tiny, 1e6 + tiny});
  Mesh pushed{
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -2}, {0, 0, -1}},
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  const std::vector<std::pair<Mesh, std::string>> bad = {
      {reversed(unit), "a reversed box"},
      {joined(box_mesh({5, 0.5, 0.5}, {6, 2, 2}), reversed(unit)), "beside a reversed box"},
      {pushed, "octahedron pushed through"},
      {joined(big, unit), "nested in one direction"},
      {joined(reversed(big), reversed(unit)), "nested, both reversed"},
      {reversed(far), "a tiny reversed box far away"}};
  for (const auto& [mesh, what] : bad) {
    EXPECT_FALSE(agree(mesh, std::vector<bool>(mesh.vertices.size(), true), what)) << what;
    EXPECT_NE(check_written(mesh).error().message.find("inside out"), std::string::npos) << what;
  }
  const std::vector<std::pair<Mesh, std::string>> good = {
      {unit, "a box"},
      {joined(big, reversed(unit)), "hollow"},
      {joined(joined(huge, reversed(big)), unit), "three nested"},
      {joined(unit, box_mesh({1, 1, 1}, {2, 2, 2})), "touching at a corner"},
      {far, "a tiny box far away"}};
  for (const auto& [mesh, what] : good)
    EXPECT_TRUE(agree(mesh, std::vector<bool>(mesh.vertices.size(), true), what)) << what;
}

}  // namespace
}  // namespace contain::test
