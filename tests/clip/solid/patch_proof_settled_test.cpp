// PatchProofs::settled (the pair stage's proof per subtree, through the neighbours across edges
// and the turns kept by the star proofs) agrees with the full path, embedded_patch on the
// subtree's triangles (its boundary by a sort of their half-edges, the turns by orient2d), on
// every node of the hierarchy of soups whose triangles overlap: bumped and dented icospheres
// folding through themselves, crossing and duplicated spheres in one input, and small integer
// polyhedra whose faces overlap in their planes, share edges and touch at vertices. A settled
// node is also checked by brute force (no two of its triangles meet beyond their shared corners
// or edge, exactly): so the test fails whenever settled claims a patch wrongly, whether or not
// embedded_patch would have claimed it too.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/patch_proof.h"
#include "clip/solid/solid_oracle.h"
#include "clip/solid/star_proof.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/triangles_meet.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::solid::Soup;

// The triangles of the subtree under `node` of the soup's hierarchy (its leaves' items).
std::vector<std::int32_t> triangles_below(const Soup& soup, std::int32_t node) {
  const std::span<const bvh::Node> nodes = soup.tree.nodes();
  std::vector<std::int32_t> below;
  std::vector<std::int32_t> stack{node};
  while (!stack.empty()) {
    const std::int32_t index = stack.back();
    stack.pop_back();
    const bvh::Node& n = nodes[static_cast<std::size_t>(index)];
    if (n.is_leaf()) {
      for (std::int32_t k = n.first; k < n.first + n.count; ++k)
        below.push_back(soup.tree.items()[static_cast<std::size_t>(k)]);
    } else {
      stack.push_back(index + 1);
      stack.push_back(n.first);
    }
  }
  return below;
}

Triangle3 corners_of_triangle(const Soup& soup, std::int32_t t) {
  const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(t)];
  return {soup.vertices[static_cast<std::size_t>(v[0])],
          soup.vertices[static_cast<std::size_t>(v[1])],
          soup.vertices[static_cast<std::size_t>(v[2])]};
}

// Brute force, exactly: two of the triangles meet beyond the corners they share (by position),
// or one has zero area or comes twice.
bool two_of_them_meet(const Soup& soup, const std::vector<std::int32_t>& triangles) {
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Triangle3 a = corners_of_triangle(soup, triangles[i]);
    if (predicates::collinear(a.a, a.b, a.c)) return true;
    for (std::size_t j = i + 1; j < triangles.size(); ++j) {
      const Triangle3 b = corners_of_triangle(soup, triangles[j]);
      const std::array<int, 3> shared = predicates::shared_corners(a, b);
      if (shared[0] >= 0 && shared[1] >= 0 && shared[2] >= 0) return true;
      if (predicates::triangles_meet_beyond_shared(a, b, shared)) return true;
    }
  }
  return false;
}

// What the nodes of the soups checked came to.
struct SettledTally {
  std::size_t settled = 0;  // claimed, and found sound by brute force
  std::size_t refused = 0;  // proven corners, one input, one turn: refused by the full path
  std::size_t crossed = 0;  // of those, nodes whose triangles meet (overlap, cross, touch)
};

// Every node of the soup's hierarchy: settled exactly when the node is inner, its triangles of
// one input with every corner proven, and embedded_patch holds for them; a settled node's
// triangles never meet.
void expect_settled_agrees(const Soup& soup, const std::string& what, SettledTally& tally) {
  // The pair stage's path: the stars in leaf order, `across` taken over by the proofs
  // (`corners`, by triangle, stays).
  clip::solid::ProvenStars stars = clip::solid::proven_stars(soup, clip::solid::StarOrder::leaf);
  const clip::solid::PatchProofs proofs = clip::solid::PatchProofs::from_leaf_order(soup, stars);
  const std::span<const bvh::Node> nodes = soup.tree.nodes();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto node = static_cast<std::int32_t>(i);
    const bool settled = proofs.settled(node);
    const std::vector<std::int32_t> below = triangles_below(soup, node);
    bool candidate = !nodes[i].is_leaf();
    for (const std::int32_t t : below) {
      candidate = candidate && stars.corners[static_cast<std::size_t>(t)] == 7 &&
                  soup.input[static_cast<std::size_t>(t)] ==
                      soup.input[static_cast<std::size_t>(below.front())];
    }
    const bool embedded = candidate && clip::solid::embedded_patch(soup, below);
    EXPECT_EQ(settled, embedded) << what << ": node " << i << " of " << below.size()
                                 << " triangles";
    if (settled) {
      EXPECT_FALSE(two_of_them_meet(soup, below)) << what << ": node " << i;
      ++tally.settled;
    } else if (candidate) {
      ++tally.refused;
      tally.crossed += two_of_them_meet(soup, below) ? 1 : 0;
    }
  }
}

// A soup of the meshes' triangles as they are (no welding: equal positions stay distinct
// vertices), each mesh's triangles of input `inputs[k]`.
Soup unwelded_soup(const std::vector<Mesh>& meshes, const std::vector<std::int32_t>& inputs) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::vector<std::int32_t> input;
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    const auto offset = static_cast<std::int32_t>(vertices.size());
    vertices.insert(vertices.end(), meshes[k].vertices.begin(), meshes[k].vertices.end());
    for (const TriangleIndices& t : meshes[k].triangles) {
      triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
      input.push_back(inputs[k]);
    }
  }
  Soup soup = raw_soup(vertices, triangles);
  soup.input = input;
  soup.inputs = 2;
  return soup;
}

// Every vertex moved along its radius from `center` by a factor drawn from [lo, hi]: wide
// ranges fold triangles through the far side (saddles and proven cones, convex or concave).
Mesh bumped(Mesh mesh, Vec3 center, double lo, double hi, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> factor(lo, hi);
  for (Vec3& v : mesh.vertices) {
    const double f = factor(rng);
    v = {center.x + (v.x - center.x) * f, center.y + (v.y - center.y) * f,
         center.z + (v.z - center.z) * f};
  }
  return mesh;
}

TEST(PatchProofSettled, AgreesWithTheFullPathOnFoldedBumpedAndDentedSpheres) {
  std::mt19937_64 rng(2026);
  SettledTally tally;
  const int cases = case_budget(24, 4);
  for (int k = 0; k < cases; ++k) {
    const Vec3 o{0, 0, 0};
    // Gentle bumps (mostly proven, settled subtrees), wide ones (folds through the far side).
    const double spread = std::array{0.02, 0.3, 0.8}[static_cast<std::size_t>(k % 3)];
    Mesh mesh = bumped(icosphere(2, 1.0, o), o, 1.0 - spread, 1.0 + spread, rng);
    // A dent: the cap beyond a plane turned inside out and stretched through the far side (a
    // bowl of proven cones, its pole beyond the far side, its rim inside the sphere).
    if (k % 2 == 1) {
      const Vec3 a = mesh.vertices[static_cast<std::size_t>(k) % mesh.vertices.size()];
      const double l = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
      const Vec3 axis{a.x / l, a.y / l, a.z / l};
      for (Vec3& v : mesh.vertices) {
        const double h = v.x * axis.x + v.y * axis.y + v.z * axis.z;
        if (h <= 0.5) continue;
        const double shift = h - (-2.5 * (h - 0.5) - 0.1);
        v = {v.x - shift * axis.x, v.y - shift * axis.y, v.z - shift * axis.z};
      }
    }
    expect_settled_agrees(unwelded_soup({mesh}, {0}), "sphere " + std::to_string(k), tally);
  }
  EXPECT_GT(tally.settled, 0U);
  EXPECT_GT(tally.crossed, 0U);
}

TEST(PatchProofSettled, AgreesWithTheFullPathOnCrossingAndDuplicatedSpheres) {
  SettledTally tally;
  const Mesh a = icosphere(2, 1.0, {0, 0, 0});
  // The same sphere twice (every triangle overlapping its copy in its plane), a shifted one
  // crossing it, a smaller one inside touching nothing, and one touching it at a vertex by
  // position (the icosphere is symmetric through its centre: its vertex -v reflected).
  const Vec3 v = a.vertices[0];
  const std::vector<std::pair<Mesh, std::string>> others = {
      {a, "duplicate"},
      {icosphere(2, 1.0, {0.4, 0.3, 0.2}), "crossing"},
      {icosphere(2, 0.5, {0.1, 0, 0}), "inside"},
      {icosphere(2, 1.0, {2 * v.x, 2 * v.y, 2 * v.z}), "touching at a vertex"},
      {reversed(icosphere(2, 0.9, {0.2, 0.1, 0})), "inside out, crossing"}};
  for (const auto& [b, what] : others) {
    // One input (self-intersecting: its subtrees are tried), and two.
    expect_settled_agrees(unwelded_soup({a, b}, {0, 0}), what + ", one input", tally);
    expect_settled_agrees(unwelded_soup({a, b}, {0, 1}), what + ", two inputs", tally);
  }
  EXPECT_GT(tally.settled, 0U);
  EXPECT_GT(tally.crossed, 0U);
}

// A tetrahedron of integer corners, outward, or nothing when flat.
std::vector<Mesh> integer_tetrahedron(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(0, 3);
  const auto corner = [&] {
    return Vec3{static_cast<double>(c(rng)), static_cast<double>(c(rng)),
                static_cast<double>(c(rng))};
  };
  const Vec3 p = corner(), q = corner(), r = corner(), s = corner();
  if (predicates::orient3d(p, q, r, s) == Sign::zero) return {};
  return {tetrahedron(p, q, r, s)};
}

// An octahedron of radius 1 about an integer centre (its corners on the axes).
Mesh integer_octahedron(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(0, 3);
  const Vec3 o{static_cast<double>(c(rng)), static_cast<double>(c(rng)),
               static_cast<double>(c(rng))};
  Mesh m;
  m.vertices = {{o.x + 1, o.y, o.z}, {o.x - 1, o.y, o.z}, {o.x, o.y + 1, o.z},
                {o.x, o.y - 1, o.z}, {o.x, o.y, o.z + 1}, {o.x, o.y, o.z - 1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

TEST(PatchProofSettled, AgreesWithTheFullPathOnIntegerPolyhedraOverlappingInTheirPlanes) {
  // Corners on a 4 x 4 x 4 grid: faces overlap in common planes, share edges and corners by
  // position and cross; every corner of a tetrahedron or an octahedron is a proven cone.
  std::mt19937_64 rng(25);
  SettledTally tally;
  const int cases = case_budget(300, 10);
  for (int k = 0; k < cases; ++k) {
    std::vector<Mesh> meshes;
    std::vector<std::int32_t> inputs;
    const int pieces = 2 + k % 12;
    for (int p = 0; p < pieces; ++p) {
      std::vector<Mesh> piece =
          p % 3 == 2 ? std::vector<Mesh>{integer_octahedron(rng)} : integer_tetrahedron(rng);
      for (Mesh& m : piece) {
        meshes.push_back(std::move(m));
        inputs.push_back(k % 4 == 3 ? p % 2 : 0);
      }
    }
    if (meshes.empty()) continue;
    expect_settled_agrees(unwelded_soup(meshes, inputs), "polyhedra " + std::to_string(k), tally);
  }
  EXPECT_GT(tally.settled, 0U);
  EXPECT_GT(tally.refused, 0U);
  EXPECT_GT(tally.crossed, 0U);
}

}  // namespace
}  // namespace contain::test
