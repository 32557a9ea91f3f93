#pragma once
// The sign of an expression written once over a number type T: the running-error filter first
// (Bounded: answers unless the value lies within its proven error bound, or is an exact
// zero), then BigFloat (exact for every finite double).

#include "contain/predicates/big_float.h"
#include "contain/predicates/bounded.h"

namespace contain::predicates::detail {

template <class F>
[[nodiscard]] Sign filtered_sign(F&& f) {
  const Bounded fast = f(Bounded{});
  if (fast.decided()) return fast.sign();
  return f(BigFloat{}).sign();
}

}  // namespace contain::predicates::detail
