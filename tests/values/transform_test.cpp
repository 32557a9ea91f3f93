#include "contain/values/transform.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace contain {
namespace {

TEST(Transform, ReadsTheContractRowOrderAndAppliesRxPlusT) {
  const std::vector<double> shift_x{1, 0, 0, 2.5, 0, 1, 0, 0, 0, 0, 1, 0};
  auto t = Transform::from_row_major(shift_x);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->apply({1, 2, 3}), (Vec3{3.5, 2, 3}));
  const std::vector<double> rot_z{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 1};
  auto r = Transform::from_row_major(rot_z);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->apply({1, 0, 0}), (Vec3{0, 1, 1}));
}

TEST(Transform, RejectsAWrongCountAndNaN) {
  const std::vector<double> eleven(11, 0.0);
  EXPECT_FALSE(Transform::from_row_major(eleven).ok());
  std::vector<double> nan(12, 0.0);
  nan[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(Transform::from_row_major(nan).ok());
}

}  // namespace
}  // namespace contain
