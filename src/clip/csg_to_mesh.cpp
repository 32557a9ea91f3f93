// A CSG tree to one mesh: check every leaf is polyhedral, find the tree's box (for the leaves
// that may be unbounded), then one mesh_boolean per operation node, bottom-up.
//
// Why one box for the whole tree is enough: evaluating each unbounded leaf L as L' = L ∩ B keeps,
// for every node, S' ∩ B = S ∩ B (S its solid, S' its evaluation): leaves by construction, and
// union, intersection, difference and complement (B minus the operand) commute with ∩ B. Where
// the root's box is known (`solid_box`), S' stays inside it (by the same rules, node by node), and
// B holds it, so S' = S' ∩ B = S ∩ B = S.

#include "contain/clip/csg_to_mesh.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contain/clip/csg_leaf_mesh.h"
#include "contain/values/box.h"

namespace contain::clip {
namespace {

std::string operand_path(const std::string& path, CsgOp op, std::size_t i) {
  if (op == CsgOp::complement) return path + "complement.";
  return path + shapes::to_string(op) + "[" + std::to_string(i) + "].";
}

Error at(const std::string& path, Error error) {
  std::string where = path;
  if (!where.empty() && where.back() == '.') where.pop_back();
  if (!where.empty()) error.message = where + ": " + error.message;
  return error;
}

// Every leaf polyhedral, before any boolean runs: the first one that is not, by its path.
Status check_polyhedral(const Csg& node, const std::string& path) {
  if (node.op() == CsgOp::leaf) {
    const bool sphere = std::holds_alternative<Sphere>(node.solid());
    if (!sphere && !std::holds_alternative<ImplicitFunction>(node.solid())) return Ok{};
    return at(path + (sphere ? "sphere" : "implicit"), csg_leaf_mesh(node.solid(), {}).error());
  }
  for (std::size_t i = 0; i < node.operands().size(); ++i) {
    if (Status s = check_polyhedral(node.operands()[i], operand_path(path, node.op(), i)); !s) {
      return s;
    }
  }
  return Ok{};
}

// A box holding the node's solid, or nothing where it may be unbounded.
std::optional<Box3> solid_box(const Csg& node) {
  const auto operands = node.operands();
  switch (node.op()) {
    case CsgOp::leaf:
      return csg_leaf_box(node.solid());
    case CsgOp::unite: {
      Box3 box;
      for (const Csg& operand : operands) {
        const std::optional<Box3> b = solid_box(operand);
        if (!b) return std::nullopt;
        box.expand(*b);
      }
      return box;
    }
    case CsgOp::intersection: {
      std::optional<Box3> box;
      for (const Csg& operand : operands) {
        const std::optional<Box3> b = solid_box(operand);
        if (!b) continue;
        if (!box) {
          box = b;
          continue;
        }
        box->min = {std::max(box->min.x, b->min.x), std::max(box->min.y, b->min.y),
                    std::max(box->min.z, b->min.z)};
        box->max = {std::min(box->max.x, b->max.x), std::min(box->max.y, b->max.y),
                    std::min(box->max.z, b->max.z)};
      }
      return box;
    }
    case CsgOp::difference:
      return solid_box(operands[0]);
    case CsgOp::complement:
      return std::nullopt;
  }
  return std::nullopt;
}

// The box grown by a quarter of its largest side (so that the cut faces of unbounded leaves lie
// off the solid), or as it is where growing would overflow.
Box3 grown(const Box3& box) {
  const Vec3 size = box.max - box.min;
  double margin = 0.25 * std::max({size.x, size.y, size.z});
  if (margin == 0) margin = 1;
  const Vec3 m{margin, margin, margin};
  const Box3 out{box.min - m, box.max + m};
  const bool finite = std::isfinite(out.min.x) && std::isfinite(out.min.y) &&
                      std::isfinite(out.min.z) && std::isfinite(out.max.x) &&
                      std::isfinite(out.max.y) && std::isfinite(out.max.z);
  return finite ? out : box;
}

struct Evaluator {
  Box3 bounds;
  std::size_t moved = 0;  // by every call
  // The counts of the last call, which is the root's: operands are evaluated before their node.
  std::size_t shells = 0;
  double volume = 0;

  Result<Mesh> boolean(const std::string& path, const std::vector<Mesh>& inputs, Op op) {
    auto result = mesh_boolean(inputs, {.op = op});
    if (!result) return at(path, result.error());
    moved += result->moved;
    shells = result->shells;
    volume = result->volume;
    return std::move(result->mesh);
  }

  // The operands of a union or an intersection, with those of nested nodes of the same kind.
  Status gather(const Csg& node, const std::string& path, std::vector<Mesh>& meshes) {
    for (std::size_t i = 0; i < node.operands().size(); ++i) {
      const Csg& operand = node.operands()[i];
      const std::string at_operand = operand_path(path, node.op(), i);
      if (operand.op() == node.op()) {
        if (Status s = gather(operand, at_operand, meshes); !s) return s;
        continue;
      }
      auto mesh = evaluate(operand, at_operand);
      if (!mesh) return mesh.error();
      meshes.push_back(std::move(*mesh));
    }
    return Ok{};
  }

  Result<Mesh> evaluate(const Csg& node, const std::string& path) {
    std::vector<Mesh> inputs;
    switch (node.op()) {
      case CsgOp::leaf: {
        auto mesh = csg_leaf_mesh(node.solid(), bounds);
        if (!mesh) return at(path, mesh.error());
        return mesh;
      }
      case CsgOp::unite:
      case CsgOp::intersection: {
        if (node.op() == CsgOp::intersection && node.operands().empty()) {
          return csg_leaf_mesh(bounds, bounds);  // all of space, inside the box
        }
        if (Status s = gather(node, path, inputs); !s) return s.error();
        return boolean(path + shapes::to_string(node.op()), inputs,
                       node.op() == CsgOp::unite ? Op::union_ : Op::intersection);
      }
      case CsgOp::difference: {
        const Csg& a = node.operands()[0];
        const Csg& b = node.operands()[1];
        auto first = evaluate(a, operand_path(path, node.op(), 0));
        if (!first) return first;
        inputs.push_back(std::move(*first));
        if (b.op() == CsgOp::unite) {
          if (Status s = gather(b, operand_path(path, node.op(), 1), inputs); !s) return s.error();
        } else {
          auto second = evaluate(b, operand_path(path, node.op(), 1));
          if (!second) return second;
          inputs.push_back(std::move(*second));
        }
        return boolean(path + shapes::to_string(node.op()), inputs, Op::difference);
      }
      case CsgOp::complement: {
        auto box = csg_leaf_mesh(bounds, bounds);
        auto operand = evaluate(node.operands()[0], operand_path(path, node.op(), 0));
        if (!operand) return operand;
        inputs.push_back(std::move(*box));
        inputs.push_back(std::move(*operand));
        return boolean(path + shapes::to_string(node.op()), inputs, Op::difference);
      }
    }
    return Mesh{};
  }
};

}  // namespace

Result<MeshBooleanResult> csg_to_mesh(const Csg& tree) {
  if (Status s = check_polyhedral(tree, ""); !s) return s.error();
  const std::optional<Box3> box = solid_box(tree);
  if (!box) {
    return Error{ErrorKind::invalid_value,
                 "the CSG tree's solid is unbounded (a half-space, a convex polyhedron given by "
                 "planes or a complement outside any intersection with a bounded solid): "
                 "intersect it with a box"};
  }
  Evaluator evaluator{.bounds = grown(*box)};
  auto mesh = evaluator.evaluate(tree, "");
  if (!mesh) return mesh.error();
  if (tree.op() != CsgOp::leaf) {
    return MeshBooleanResult{.mesh = std::move(*mesh),
                             .shells = evaluator.shells,
                             .volume = evaluator.volume,
                             .moved = evaluator.moved};
  }
  // A lone leaf is repaired, so that the result is a valid mesh whatever the leaf was.
  const Mesh leaf[] = {std::move(*mesh)};
  auto result = mesh_boolean(leaf, {.op = Op::union_});
  return result;
}

}  // namespace contain::clip
