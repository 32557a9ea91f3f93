// The edge uses that the labels build over the refined faces, narrowed by boundary_faces to the
// result's faces and walked again by the merging of coplanar faces (issue 25: built once, not
// twice): they equal a build over the boundary's faces, and the merging gives the same faces
// from them as from its own build, on boxes whose faces coincide, overlap in part and touch
// (coplanar regions merged) and on crossing spheres, for every operation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
#include "clip/solid/engine.h"
#include "clip/solid/snap.h"
#include "clip/solid/solid_oracle.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::Op;
using clip::solid::BoundaryFaces;
using clip::solid::EdgeUses;
using clip::solid::Faces;

// The boundary of `op` on the inputs as the engine makes it (its uses the labels' narrowed),
// with the store it numbers points in.
struct StagedBoundary {
  clip::solid::PointStore store;
  clip::solid::Soup soup;
  BoundaryFaces boundary;
};

StagedBoundary staged_boundary(const std::vector<Mesh>& inputs, Op op) {
  StagedBoundary out;
  Result<clip::solid::Soup> soup = clip::solid::make_soup(inputs);
  EXPECT_TRUE(soup.ok());
  if (!soup.ok()) return out;
  out.soup = std::move(*soup);
  out.store.add_vertices(out.soup);
  const std::vector<clip::solid::TriangleWork> work =
      clip::solid::intersect_pairs(out.soup, out.store);
  const clip::solid::Refinement refinement = clip::solid::refine(out.soup, work, out.store);
  clip::solid::FaceLabels labels = clip::solid::label_faces(out.soup, refinement, out.store);
  out.boundary =
      clip::solid::boundary_faces(out.soup, refinement, work, std::move(labels), out.store, op);
  return out;
}

// Returns the number of boundary faces (that the cases were not empty).
std::size_t expect_shared_uses_as_built(const std::vector<Mesh>& inputs, Op op,
                                        const std::string& what) {
  StagedBoundary staged = staged_boundary(inputs, op);
  const BoundaryFaces& boundary = staged.boundary;
  const EdgeUses built = clip::solid::edge_uses(
      boundary.faces.size(), [&](std::size_t f) -> const auto& { return boundary.faces[f]; });
  EXPECT_EQ(boundary.uses.start, built.start) << what;
  EXPECT_TRUE(std::equal(boundary.uses.entry.begin(), boundary.uses.entry.end(),
                         built.entry.begin(), built.entry.end()))
      << what;
  // The merging from the shared uses and from its own build (uses left empty), each adding its
  // enclosing corners to its own copy of the store.
  clip::solid::PointStore own_store = staged.store;
  BoundaryFaces unshared{boundary.faces, boundary.triangle, {}};
  const Faces shared_merge = clip::solid::merge_coplanar(staged.soup, boundary, staged.store);
  const Faces own_merge = clip::solid::merge_coplanar(staged.soup, unshared, own_store);
  EXPECT_EQ(shared_merge, own_merge) << what;
  EXPECT_EQ(staged.store.size(), own_store.size()) << what;
  return boundary.faces.size();
}

TEST(BoundaryUses, NarrowedLabelUsesEqualABuildOverLatticeBoxesBoundaryForEveryOperation) {
  std::mt19937_64 rng(25);
  std::uniform_int_distribution<int> c(0, 4);
  const auto lattice_box = [&] {
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = c(rng);
      hi[k] = c(rng);
      if (lo[k] > hi[k]) std::swap(lo[k], hi[k]);
      if (lo[k] == hi[k]) ++hi[k];
    }
    return box_mesh({double(lo[0]), double(lo[1]), double(lo[2])},
                    {double(hi[0]), double(hi[1]), double(hi[2])});
  };
  std::size_t faces = 0;
  for (int t = 0; t < case_budget(30, 3); ++t) {
    const std::vector<Mesh> in = {lattice_box(), lattice_box(), lattice_box()};
    for (const Op op : {Op::union_, Op::intersection, Op::difference, Op::xor_})
      faces += expect_shared_uses_as_built(in, op, "case " + std::to_string(t));
  }
  EXPECT_GT(faces, 0U);
}

TEST(BoundaryUses, NarrowedLabelUsesEqualABuildOverCrossingSpheresBoundaryForEveryOperation) {
  const std::vector<Mesh> in = {icosphere(3, 1.0, {0, 0, 0}), icosphere(3, 1.0, {0.5, 0.4, 0.3})};
  for (const Op op : {Op::union_, Op::intersection, Op::difference, Op::xor_})
    EXPECT_GT(expect_shared_uses_as_built(in, op, "spheres"), 100U);
}

}  // namespace
}  // namespace contain::test
