#include "contain/shapes/csg.h"

namespace contain::shapes {

const char* to_string(CsgOp op) {
  switch (op) {
    case CsgOp::leaf:
      break;
    case CsgOp::unite:
      return "union";
    case CsgOp::intersection:
      return "intersection";
    case CsgOp::difference:
      return "difference";
    case CsgOp::complement:
      return "complement";
  }
  return "leaf";
}

Csg Csg::leaf(CsgLeaf solid) {
  return Csg(CsgOp::leaf, {}, std::make_shared<const CsgLeaf>(std::move(solid)));
}
Csg Csg::unite(std::vector<Csg> operands) {
  return Csg(CsgOp::unite, std::move(operands), {});
}
Csg Csg::intersection(std::vector<Csg> operands) {
  return Csg(CsgOp::intersection, std::move(operands), {});
}
Csg Csg::difference(Csg a, Csg b) {
  std::vector<Csg> operands;
  operands.push_back(std::move(a));
  operands.push_back(std::move(b));
  return Csg(CsgOp::difference, std::move(operands), {});
}
Csg Csg::complement(Csg a) {
  std::vector<Csg> operands;
  operands.push_back(std::move(a));
  return Csg(CsgOp::complement, std::move(operands), {});
}

}  // namespace contain::shapes
