#pragma once
/// \file
/// Exact conversion of a rational number written in decimal (numerator / denominator, integers of
/// any length) into the double it equals, if it is one: how the CCD benchmark's files (Wang et
/// al. 2021) store coordinates, which must be read without rounding.

#include <optional>
#include <string_view>

namespace contain::predicates {

/// The double equal to numerator / denominator, or nothing when that rational is not exactly a
/// double (or a string is not an integer: optional sign, then decimal digits; or the
/// denominator is zero). Any length of digits; exact (big-number comparisons q * den == num).
/// At most ~64 exact comparisons.
[[nodiscard]] std::optional<double> rational_to_double(std::string_view numerator,
                                                       std::string_view denominator);

}  // namespace contain::predicates
