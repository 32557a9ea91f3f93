#pragma once
/// \file
/// CSG trees as data (exercise 22.4-2): unions, intersections, differences and complements of
/// balls, boxes, half-spaces, convex polyhedra, closed triangle meshes and implicit solids. A tree
/// is a value built bottom-up; inside::CsgSolid validates it, prepares it and locates points in
/// it, with the regularised operations of solid modelling (semantics in inside/csg.h).
///
/// Data here, queries in inside: a tree is what readers (io::read_csg_json) produce and writers
/// and other queries (clipping, distance) may consume, none of which needs a point locator.

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/implicit_function.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/sphere.h"

namespace contain::shapes {

/// A closed triangle mesh as a CSG leaf: the solid inside::MeshIndex reads in it (winding number
/// positive, so a shell turned inside out subtracts; crossing parity only for a closed mesh
/// whose orientation is inconsistent: inside::solid_rule). Holds the mesh, shared by copies.
/// inside::CsgSolid::prepare refuses a mesh with a NaN/Inf coordinate or an index out of range
/// (invalid_value) and a mesh that is not closed (degenerate: border edges leave the winding
/// number undefined).
class CsgMesh {
 public:
  /// Any contents; problems are reported by inside::CsgSolid::prepare.
  explicit CsgMesh(Mesh mesh) : mesh_(std::make_shared<const Mesh>(std::move(mesh))) {}

  [[nodiscard]] const Mesh& mesh() const { return *mesh_; }

 private:
  std::shared_ptr<const Mesh> mesh_;
};

/// A leaf solid: a closed ball, a closed box, a closed half-space (a x + b y + c z + d >= 0), a
/// convex polyhedron (from planes or a convex mesh), { p : f(p) >= 0 }, or a closed mesh.
using CsgLeaf = std::variant<Sphere, Box3, Plane, ConvexPolyhedron, ImplicitFunction, CsgMesh>;

/// The kind of a CSG node.
enum class CsgOp : std::uint8_t {
  leaf,
  unite,         ///< union of the operands; of none: the empty set
  intersection,  ///< intersection of the operands; of none: all of space
  difference,    ///< first operand minus the second
  complement,    ///< the (closure of the) complement of the one operand
};

/// A CSG tree as a value: leaves and operations, built bottom-up. Not validated: prepare it with
/// inside::CsgSolid::prepare. Copies share their leaves.
class Csg {
 public:
  /// A leaf: Csg::leaf(Sphere{{0, 0, 0}, 1}), Csg::leaf(Box3{min, max}), ...
  [[nodiscard]] static Csg leaf(CsgLeaf solid);
  [[nodiscard]] static Csg unite(std::vector<Csg> operands);
  [[nodiscard]] static Csg intersection(std::vector<Csg> operands);
  [[nodiscard]] static Csg difference(Csg a, Csg b);
  [[nodiscard]] static Csg complement(Csg a);

  [[nodiscard]] CsgOp op() const { return op_; }
  /// The operands of an operation (two for difference, one for complement, none for a leaf).
  [[nodiscard]] std::span<const Csg> operands() const { return operands_; }
  /// The solid of a leaf. Precondition: op() == CsgOp::leaf.
  [[nodiscard]] const CsgLeaf& solid() const { return *leaf_; }

 private:
  Csg(CsgOp op, std::vector<Csg> operands, std::shared_ptr<const CsgLeaf> leaf)
      : op_(op), operands_(std::move(operands)), leaf_(std::move(leaf)) {}

  CsgOp op_;
  std::vector<Csg> operands_;
  std::shared_ptr<const CsgLeaf> leaf_;
};

/// The operation's word in the CSG JSON grammar and Python's `Csg.op`: `leaf`, `union`,
/// `intersection`, `difference`, `complement` (`unite` is spelt `union` there, a C++ keyword).
[[nodiscard]] const char* to_string(CsgOp op);

}  // namespace contain::shapes

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::Csg;
using shapes::CsgLeaf;
using shapes::CsgMesh;
using shapes::CsgOp;
}  // namespace contain
