#include "contain/predicates/orient3d.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// ((b - a) x (c - a)) . (d - a) from the differences (b - a, c - a, d - a) as exact numbers.
template <class D>
Sign orient3d_of(const std::array<D, 9>& d) {
  const auto nx = d[1] * d[5] - d[2] * d[4];
  const auto ny = d[2] * d[3] - d[0] * d[5];
  const auto nz = d[0] * d[4] - d[1] * d[3];
  return (nx * d[6] + ny * d[7] + nz * d[8]).sign();
}

}  // namespace

namespace {

// Differences with tails, out of line (see orient2d.cpp: keeps the fast path free of stalls).
[[gnu::noinline]] Sign orient3d_general(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  std::array<Expansion<2>, 9> diff;
  (void)differences(std::array{b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z},
                    std::array{a.x, a.y, a.z, a.x, a.y, a.z, a.x, a.y, a.z}, diff);
  return orient3d_of(diff);
}

// p q - r s exactly, as an expansion of at most four components, smallest first, zeros
// dropped (on lattice input it is usually one double, which keeps the scaling below short).
int two_by_two(double p, double q, double r, double s, double* out) {
  double l1, l0, r1, r0;
  two_product(p, q, l1, l0);
  two_product(r, s, r1, r0);
  double x[4];
  two_two_diff(l1, l0, r1, r0, x[3], x[2], x[1], x[0]);
  int n = 0;
  for (const double c : x) {
    if (c != 0.0) out[n++] = c;
  }
  return n;
}

}  // namespace

Sign orient3d_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  double u[3], v[3], w[3], ut[3], vt[3], wt[3];
  two_diff(b.x, a.x, u[0], ut[0]);
  two_diff(b.y, a.y, u[1], ut[1]);
  two_diff(b.z, a.z, u[2], ut[2]);
  two_diff(c.x, a.x, v[0], vt[0]);
  two_diff(c.y, a.y, v[1], vt[1]);
  two_diff(c.z, a.z, v[2], vt[2]);
  two_diff(d.x, a.x, w[0], wt[0]);
  two_diff(d.y, a.y, w[1], wt[1]);
  two_diff(d.z, a.z, w[2], wt[2]);
  const bool exact = ut[0] == 0.0 && ut[1] == 0.0 && ut[2] == 0.0 && vt[0] == 0.0 && vt[1] == 0.0 &&
                     vt[2] == 0.0 && wt[0] == 0.0 && wt[1] == 0.0 && wt[2] == 0.0;
  if (!exact) return orient3d_general(a, b, c, d);
  // Exact differences (Shewchuk's stage B): (u x v) . w with each cross component a
  // four-component Two-Two-Diff, scaled by one double, then summed: at most 24 components.
  double n[3][4];
  int nn[3];
  nn[0] = two_by_two(u[1], v[2], u[2], v[1], n[0]);
  nn[1] = two_by_two(u[2], v[0], u[0], v[2], n[1]);
  nn[2] = two_by_two(u[0], v[1], u[1], v[0], n[2]);
  double t[3][8];
  int tn[3];
  for (int i = 0; i < 3; ++i) {
    tn[i] = scale_expansion_zeroelim(nn[i], n[i], w[i], t[i]);
  }
  double s1[16];
  const int s1n = fast_expansion_sum_zeroelim(tn[0], t[0], tn[1], t[1], s1);
  double s2[24];
  const int s2n = fast_expansion_sum_zeroelim(s1n, s1, tn[2], t[2], s2);
  return s2n == 0 ? Sign::zero : sign_of(s2[s2n - 1]);
}

Sign orient3d_big(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const BigFloat ax(a.x), ay(a.y), az(a.z);
  return orient3d_of(std::array{BigFloat(b.x) - ax, BigFloat(b.y) - ay, BigFloat(b.z) - az,
                                BigFloat(c.x) - ax, BigFloat(c.y) - ay, BigFloat(c.z) - az,
                                BigFloat(d.x) - ax, BigFloat(d.y) - ay, BigFloat(d.z) - az});
}

namespace {

// Inputs beyond the expansion range: rescaled into it if their exponents allow, else big
// numbers. Out of line so that the fast path does not pay for packing these arrays.
[[gnu::noinline]] Sign orient3d_extreme(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  std::array v{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (scale_into_expansion_range<3>(v)) {
    return orient3d_expansion({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]},
                              {v[9], v[10], v[11]});
  }
  return orient3d_big(a, b, c, d);
}

}  // namespace

Sign orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (in_expansion_range<3>(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z)) {
    return orient3d_expansion(a, b, c, d);
  }
  return orient3d_extreme(a, b, c, d);
}

}  // namespace detail

}  // namespace contain::predicates
