// Degree bounds of polynomial gcds from gcds modulo primes: a cheap exact certificate that two
// polynomials have no common root, so that the sign of one at a root of the other is not zero and
// a refinement of the root decides it (polynomial_filter.cpp) without a Tarski query.
//
// Why it bounds: with a and b scaled by powers of two to integer polynomials (2 is invertible
// modulo an odd prime, so the residues are those of the scaled polynomials up to units), a common
// factor g of a and b over the rationals is, by Gauss's lemma, a primitive integer polynomial
// dividing both; modulo a prime p that divides neither leading coefficient, g's leading
// coefficient does not vanish, so g mod p is a common factor of degree deg g of a mod p and
// b mod p. Hence deg gcd(a, b) <= deg gcd(a mod p, b mod p) for every such prime.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "predicates/polynomial_state.h"

namespace contain::predicates::detail {

namespace {

using Residues = std::vector<std::uint64_t>;

// Primes below 2^31, so that every product of two residues fits in 64 bits.
constexpr std::uint32_t kPrimes[] = {2147483647U, 2147483629U};

std::uint64_t inverse(std::uint64_t x, std::uint64_t p) {
  std::uint64_t r = 1, e = p - 2;  // Fermat: x^(p - 2) = 1 / x
  for (; e != 0; e >>= 1) {
    if ((e & 1U) != 0) r = r * x % p;
    x = x * x % p;
  }
  return r;
}

void trim(Residues& a) {
  while (!a.empty() && a.back() == 0)
    a.pop_back();
}

// a mod b over the integers modulo p (b not zero, b trimmed).
Residues remainder(Residues a, const Residues& b, std::uint64_t p) {
  const std::uint64_t inv = inverse(b.back(), p);
  while (a.size() >= b.size()) {
    const std::uint64_t f = a.back() * inv % p;
    const std::size_t shift = a.size() - b.size();
    for (std::size_t j = 0; j < b.size(); ++j)
      a[shift + j] = (a[shift + j] + (p - f) * b[j]) % p;
    a.pop_back();  // now zero
    trim(a);
  }
  return a;
}

Residues reduce(const Coeffs& c, std::uint32_t p) {
  Residues r;
  r.reserve(c.size());
  for (const BigFloat& x : c)
    r.push_back(x.residue(p));
  return r;
}

}  // namespace

int gcd_degree_bound(const Coeffs& a, const Coeffs& b) {
  int bound = std::min(degree_of(a), degree_of(b));
  for (const std::uint32_t p : kPrimes) {
    Residues x = reduce(a, p), y = reduce(b, p);
    if (x.empty() || y.empty() || x.back() == 0 || y.back() == 0) continue;  // p divides a lc
    while (!y.empty()) {
      x = remainder(std::move(x), y, p);
      std::swap(x, y);
    }
    bound = std::min(bound, static_cast<int>(x.size()) - 1);
    if (bound == 0) break;
  }
  return bound;
}

}  // namespace contain::predicates::detail
