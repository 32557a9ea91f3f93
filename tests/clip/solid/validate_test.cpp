// The check of the written mesh restricted to the triangles with a corner that is not kept gives
// the full check's answer, and both give the GMP oracle's (invalid_reason: exact areas,
// collide::self_intersections), on valid results of the engine whose vertices are then moved:
// by an ulp, by 1e-14, by rounding-sized steps and by large ones that cross or flip triangles,
// with the moved vertices marked not kept (the others are still the exact arrangement's).

#include "clip/solid/validate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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
#include "contain/collide/self_intersections.h"
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
    const clip::solid::PairWork stored = clip::solid::intersect_pairs(*soup, store);
    const clip::solid::PairWork met = clip::solid::meeting_pairs(*soup);
    ASSERT_EQ(stored.size(), met.size()) << what;
    std::size_t constraints = 0;
    for (std::size_t t = 0; t < met.size(); ++t) {
      ASSERT_EQ(stored[t].constraints.size(), met[t].constraints.size()) << what << " " << t;
      EXPECT_TRUE(std::ranges::equal(stored[t].coplanar, met[t].coplanar)) << what << " " << t;
      for (std::size_t i = 0; i < met[t].constraints.size(); ++i)
        EXPECT_EQ(stored[t].constraints[i].edge, met[t].constraints[i].edge) << what;
      constraints += met[t].constraints.size();
    }
    EXPECT_GT(constraints, 0U) << what;
  }
}

// The check's pair test (a projection along one axis where an edge line leaves the other
// triangle outside, then the exact tests by shared corners) against collide's
// self_intersections (GMP-checked) on the two triangles as a mesh: random triangles on the
// lattice {0, 1, 2}^3 and in the plane z = 0 (shared corners, shared edges, coplanar overlaps,
// folds, touching at a corner or along an edge), and fans in one plane whose outer corners are
// moved by an ulp off it or along it (the merged faces of a written result). Symmetric and
// independent of the corners' order; the same triangle twice, either way round, meets.
TEST(CheckWritten, PairTestAgreesWithSelfIntersectionsOnLatticeAndNearlyCoplanarPairs) {
  using clip::solid::written_pair_meets;
  using clip::solid::zero_area;
  std::mt19937_64 rng(25);
  std::uniform_int_distribution<int> coordinate(0, 2), coin(0, 3);
  const auto lattice = [&](bool flat) {
    return Vec3{static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng)),
                flat ? 0.0 : static_cast<double>(coordinate(rng))};
  };
  const auto decide = [](const Triangle3& a, const Triangle3& b) {
    const bool meets = written_pair_meets(a, b);
    EXPECT_EQ(written_pair_meets(b, a), meets);
    EXPECT_EQ(written_pair_meets({a.b, a.c, a.a}, {b.c, b.a, b.b}), meets);
    const Mesh pair{{a.a, a.b, a.c, b.a, b.b, b.c}, {{0, 1, 2}, {3, 4, 5}}};
    EXPECT_EQ(meets, !collide::self_intersections(pair).empty())
        << a.a.x << " " << a.a.y << " " << a.a.z << " / " << a.b.x << " " << a.b.y << " " << a.b.z
        << " / " << a.c.x << " " << a.c.y << " " << a.c.z << " | " << b.a.x << " " << b.a.y << " "
        << b.a.z << " / " << b.b.x << " " << b.b.y << " " << b.b.z << " / " << b.c.x << " " << b.c.y
        << " " << b.c.z;
    return meets;
  };
  std::array<int, 2> outcomes{};
  const int cases = case_budget(20000, 10);  // enough in the reduced build for the counts below
  for (int k = 0; k < cases; ++k) {
    const bool flat = k % 2 == 0;
    const Triangle3 a{lattice(flat), lattice(flat), lattice(flat)};
    Triangle3 b{lattice(flat), lattice(flat), lattice(flat)};
    // Shared corners: b takes some of a's (any of them, in any place).
    const std::array<Vec3, 3> ca = {a.a, a.b, a.c};
    if (coin(rng) != 0) b.a = ca[static_cast<std::size_t>(coordinate(rng))];
    if (coin(rng) == 0) b.b = ca[static_cast<std::size_t>(coordinate(rng))];
    if (zero_area(a.a, a.b, a.c) || zero_area(b.a, b.b, b.c)) continue;
    const bool same = (b.a == a.a || b.a == a.b || b.a == a.c) &&
                      (b.b == a.a || b.b == a.b || b.b == a.c) &&
                      (b.c == a.a || b.c == a.b || b.c == a.c);
    if (same) {
      EXPECT_TRUE(written_pair_meets(a, b));
      continue;
    }
    ++outcomes[decide(a, b) ? 1 : 0];
  }
  // A fan of four triangles around the origin in the plane x + 2y + 3z = 0 (exact on these
  // doubles), each pair of neighbours sharing an edge, the others the centre; then an outer
  // corner moved by an ulp in each coordinate, both ways: off the plane or along it, the pairs
  // are decided exactly (a move across a neighbour's edge folds them).
  const Vec3 o{0, 0, 0};
  std::array<Vec3, 4> rim = {Vec3{3, 0, -1}, Vec3{0, 3, -2}, Vec3{-3, 0, 1}, Vec3{0, -3, 2}};
  for (std::size_t moved = 0; moved < 4; ++moved) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const double toward : {-1e300, 1e300}) {
        std::array<Vec3, 4> r = rim;
        double* c = axis == 0 ? &r[moved].x : axis == 1 ? &r[moved].y : &r[moved].z;
        *c = std::nextafter(*c, toward);
        for (std::size_t i = 0; i < 4; ++i) {
          for (std::size_t j = i + 1; j < 4; ++j) {
            const Triangle3 a{o, r[i], r[(i + 1) % 4]}, b{o, r[j], r[(j + 1) % 4]};
            ++outcomes[decide(a, b) ? 1 : 0];
          }
        }
      }
    }
  }
  // A triangle folded onto its neighbour in the plane, and one just across it: both decided.
  EXPECT_TRUE(decide({o, rim[0], rim[1]}, {rim[1], o, Vec3{1, 1, -1}}));
  EXPECT_FALSE(decide({o, rim[0], rim[1]}, {rim[0], o, rim[3]}));
  EXPECT_GT(outcomes[0], 100);
  EXPECT_GT(outcomes[1], 100);
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

// Shells counted independently of the check: triangles joined through shared vertex numbers,
// by a breadth-first walk over each vertex's triangles.
std::size_t shells_by_walk(const Mesh& mesh) {
  std::vector<std::vector<std::size_t>> around(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::int32_t v : mesh.triangles[t])
      around[static_cast<std::size_t>(v)].push_back(t);
  }
  std::vector<bool> seen(mesh.triangles.size(), false);
  std::size_t shells = 0;
  for (std::size_t first = 0; first < mesh.triangles.size(); ++first) {
    if (seen[first]) continue;
    ++shells;
    std::vector<std::size_t> stack = {first};
    seen[first] = true;
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (const std::int32_t v : mesh.triangles[t]) {
        for (const std::size_t u : around[static_cast<std::size_t>(v)]) {
          if (!seen[u]) {
            seen[u] = true;
            stack.push_back(u);
          }
        }
      }
    }
  }
  return shells;
}

// The check reports one shell exactly when the triangles are connected through shared vertex
// numbers (the engine then writes 1 for the result's shells without counting them again), on
// valid and inside-out meshes of one and several shells: boxes apart, touching at a corner by
// position only (two shells) or sharing the corner's number (one), nested, a sheet's vertex
// split; and the engine's own results of random boxes (one shell or several), whose shell
// count must match the walk's (boxes touching along an edge or at a corner are written as
// sheets apart: several shells). A check that stops before the orientation (here at an
// unmatched edge) reports false.
TEST(CheckWritten, ReportsOneShellExactlyWhenTrianglesAreConnected) {
  const Mesh unit = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh corner = box_mesh({1, 1, 1}, {2, 2, 2});
  Mesh shared_corner = joined(unit, corner);
  // The second box's corner (1, 1, 1) given the first box's number for it: one shell.
  const auto first_at = [&](Vec3 p) {
    for (std::size_t v = 0; v < shared_corner.vertices.size(); ++v) {
      if (shared_corner.vertices[v] == p) return static_cast<std::int32_t>(v);
    }
    return std::int32_t{-1};
  };
  const std::int32_t at_corner = first_at({1, 1, 1});
  for (std::size_t t = unit.triangles.size(); t < shared_corner.triangles.size(); ++t) {
    for (std::int32_t& v : shared_corner.triangles[t]) {
      if (shared_corner.vertices[static_cast<std::size_t>(v)] == Vec3{1, 1, 1}) v = at_corner;
    }
  }
  std::vector<std::pair<Mesh, std::string>> cases = {
      {unit, "a box"},
      {reversed(unit), "a reversed box"},
      {joined(unit, box_mesh({5, 0, 0}, {6, 1, 1})), "two boxes apart"},
      {joined(unit, corner), "touching at a corner, apart by number"},
      {shared_corner, "touching at a corner, one number"},
      {joined(box_mesh({-2, -2, -2}, {3, 3, 3}), reversed(unit)), "hollow"}};
  std::mt19937_64 rng(25);
  std::uniform_int_distribution<int> coordinate(0, 3);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Mesh> parts;
    for (int k = 0; k < 3; ++k) {
      const Vec3 lo{static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng)),
                    static_cast<double>(coordinate(rng))};
      parts.push_back(box_mesh(lo, lo + Vec3{1.0 + coordinate(rng) % 3, 1.0 + coordinate(rng) % 3,
                                             1.0 + coordinate(rng) % 3}));
    }
    const Result<clip::MeshBooleanResult> r = clip::mesh_boolean(parts, {.op = Op::union_});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->shells, shells_by_walk(r->mesh)) << "union " << trial;
    cases.emplace_back(r->mesh, "union " + std::to_string(trial));
  }
  int one = 0, several = 0;
  for (const auto& [mesh, what] : cases) {
    bool one_shell = false;
    const Status status = check_written(mesh, std::vector<bool>(mesh.vertices.size(), true),
                                        nullptr, clip::solid::Edges::checked, &one_shell);
    EXPECT_EQ(status.ok(), check_written(mesh).ok()) << what;
    EXPECT_EQ(one_shell, shells_by_walk(mesh) == 1) << what;
    ++(one_shell ? one : several);
  }
  EXPECT_GE(one, 10);  // both kinds met
  EXPECT_GE(several, 4);
  // Stopped before the orientation: not reported.
  Mesh flat = unit;
  flat.vertices.push_back({0.5, 0.5, 0.0});
  flat.triangles.push_back({0, 1, static_cast<std::int32_t>(flat.vertices.size() - 1)});
  bool one_shell = true;
  EXPECT_FALSE(check_written(flat, std::vector<bool>(flat.vertices.size(), true), nullptr,
                             clip::solid::Edges::checked, &one_shell)
                   .ok());
  EXPECT_FALSE(one_shell);
}

}  // namespace
}  // namespace contain::test
