#include "contain/values/transform.h"

#include <cmath>
#include <string>

namespace contain::values {

Result<Transform> Transform::from_row_major(std::span<const double> numbers) {
  if (numbers.size() != 12) {
    return Error{ErrorKind::invalid_value,
                 "a transform needs 12 numbers (3x4 matrix [R|t] by rows), got " +
                     std::to_string(numbers.size())};
  }
  for (double v : numbers) {
    if (!std::isfinite(v)) {
      return Error{ErrorKind::invalid_value, "a transform has a NaN or infinite number"};
    }
  }
  Transform out;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col)
      out.r[row][col] = numbers[row * 4 + col];
  }
  out.t = {numbers[3], numbers[7], numbers[11]};
  return out;
}

}  // namespace contain::values
