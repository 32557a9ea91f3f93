#include "contain/shapes/csg.h"

namespace contain::shapes {

Csg Csg::leaf(CsgLeaf solid) {
  return Csg(CsgOp::leaf, {}, std::make_shared<const CsgLeaf>(std::move(solid)));
}
Csg Csg::unite(std::vector<Csg> operands) {
  return Csg(CsgOp::unite, std::move(operands), {});
}
Csg Csg::intersect(std::vector<Csg> operands) {
  return Csg(CsgOp::intersect, std::move(operands), {});
}
Csg Csg::subtract(Csg a, Csg b) {
  std::vector<Csg> operands;
  operands.push_back(std::move(a));
  operands.push_back(std::move(b));
  return Csg(CsgOp::subtract, std::move(operands), {});
}
Csg Csg::complement(Csg a) {
  std::vector<Csg> operands;
  operands.push_back(std::move(a));
  return Csg(CsgOp::complement, std::move(operands), {});
}

}  // namespace contain::shapes
