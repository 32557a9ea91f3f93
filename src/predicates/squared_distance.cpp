#include "contain/predicates/squared_distance.h"

#include "contain/predicates/bounded.h"
#include "predicates/filtered_sign.h"
#include "predicates/flat_formulas.h"

namespace contain::predicates {

namespace {

using detail::Quotient;

using detail::filtered_sign;

template <class Flat>
bool same_points(const Flat& x, const Flat& y) {
  if (x.size != y.size) return false;
  const auto n = static_cast<std::size_t>(x.size);
  for (std::size_t i = 0; i < n; ++i) {
    bool found = false;
    for (std::size_t j = 0; j < n && !found; ++j)
      found = x.points[i] == y.points[j];
    if (!found) return false;
  }
  return true;
}

template <class Pair>
Sign compare_pairs(const Pair& x, const Pair& y) {
  if (same_points(x.a, y.a) && same_points(x.b, y.b)) return Sign::zero;
  return filtered_sign([&]<class T>(const T&) {
    const Quotient<T> qx = detail::squared_distance<T>(x);
    const Quotient<T> qy = detail::squared_distance<T>(y);
    return qx.num * qy.den - qy.num * qx.den;
  });
}

template <class Pair>
Sign compare_pair_with(const Pair& x, double d) {
  return filtered_sign([&]<class T>(const T&) {
    const Quotient<T> q = detail::squared_distance<T>(x);
    return q.num - (T(d) * T(d)) * q.den;
  });
}

template <class Pair>
bool meet(const Pair& x) {
  return filtered_sign([&]<class T>(const T&) { return detail::squared_distance<T>(x).num; }) ==
         Sign::zero;
}

}  // namespace

bool same_flat(const Flat3& x, const Flat3& y) {
  return same_points(x, y);
}
bool same_flat(const Flat2& x, const Flat2& y) {
  return same_points(x, y);
}
Sign compare_squared_distances(const FlatPair3& x, const FlatPair3& y) {
  return compare_pairs(x, y);
}
Sign compare_squared_distances(const FlatPair2& x, const FlatPair2& y) {
  return compare_pairs(x, y);
}
Sign compare_squared_distance(const FlatPair3& x, double d) {
  return compare_pair_with(x, d);
}
Sign compare_squared_distance(const FlatPair2& x, double d) {
  return compare_pair_with(x, d);
}
bool flats_meet(const FlatPair3& x) {
  return meet(x);
}
bool flats_meet(const FlatPair2& x) {
  return meet(x);
}

}  // namespace contain::predicates
