// Floating-point filters in front of the exact root isolation and Tarski queries of
// polynomial.cpp, in long double with running error bounds (`BasicBounded<long double>`).
//
// Why: polynomials built from doubles of mixed magnitudes (1e300 next to 1e-300, as hostile
// continuous-collision queries give) have big-number coefficients of thousands of bits, and the
// subresultant sequences of the exact stage multiply them into hundreds of thousands: a second
// a query. Yet such signs are rarely close calls: the coefficients rounded to 53 bits, kept in
// long double's 15-bit exponent range (where no double's product of degree <= 8 overflows), and
// evaluated with a proven bound over an interval decide them in microseconds. Whatever the
// bounds leave open goes to the exact stage unchanged, so the answers stay exact.
//
// - Isolation: Descartes' rule of signs in the Bernstein basis on [lo, hi], subdivision at
//   doubles halfway in the order of doubles (so roots near 0 are reached in a few steps) with
//   certified signs there (Basu, Pollack, Roy, "Algorithms in Real Algebraic Geometry", 2nd ed.,
//   10.2). One sign variation and opposite certified end signs: exactly one root, simple, in the
//   open interval. Roots at lo or hi are divided out exactly first. Roots closer together than
//   the doubles resolve (1 - 2^-1000 next to 1 - 2^-1001) are separated in deeper frames: the
//   polynomial moved exactly onto the interval left (t = origin + width u, u in [0, 1], read from
//   its upper end when the roots hug it), whose doubles resolve anew.
// - Signs at a root: the polynomial over the root's bracket of doubles (interval Horner), the
//   bracket halved on the doubles (its signs certified the same way, exactly where not) until the
//   sign is certified or the bracket is two adjacent doubles; then, unless a gcd modulo primes
//   proves that q cannot vanish there, the exact zero test gcd(p, q mod p) (cheaper than a
//   Tarski query); then the same filter on frames moved onto the bracket, level after level,
//   until q's sign is certified (it is, q not vanishing at the root).
//
// Bounded cost: every loop has a cap (levels, calls); past one the exact stage answers.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <vector>

#include "contain/predicates/bounded.h"
#include "contain/predicates/unit_roundoff.h"
#include "predicates/double_order.h"
#include "predicates/polynomial_state.h"

namespace contain::predicates::detail {

namespace {

using Wide = BasicBounded<long double>;
using WideCoeffs = std::vector<Wide>;

// Exponents beyond which a coefficient is left to the exact stage (long double's range is
// 2^+-16382; the margin keeps products with the interval's points finite).
constexpr std::int64_t kMaxExponent = 12000;
constexpr int kMaxDegree = 12;

// c's coefficients within their bounds: BigFloat::frexp is within 2^-52 of the value relative
// (2^-50 taken), scaled by a power of two exactly. Nothing when an exponent is out of range.
std::optional<WideCoeffs> to_wide(const Coeffs& c) {
  WideCoeffs out;
  out.reserve(c.size());
  for (const BigFloat& x : c) {
    std::int64_t e = 0;
    const double m = x.frexp(e);
    if (m == 0.0) {
      out.emplace_back();
      continue;
    }
    if (e > kMaxExponent || e < -kMaxExponent) return std::nullopt;
    const long double v = std::ldexp(static_cast<long double>(m), static_cast<int>(e));
    out.emplace_back(v, std::fabs(v) * 0x1p-50L);
  }
  return out;
}

// A value whose bound covers p(t) for every t in [a, b] (doubles, a <= b): Horner on the
// interval as a bounded value (midpoint, radius rounded up).
Wide over(const WideCoeffs& p, double a, double b) {
  if (p.empty()) return {};
  const long double la = a, lb = b;
  const long double m = la + (lb - la) / 2;  // in [a, b]: rounding is monotone
  const long double r = std::max(lb - m, m - la) * (1 + 4 * unit_roundoff<long double>);
  const Wide t{m, r};
  Wide acc = p.back();
  for (std::size_t k = p.size() - 1; k-- > 0;)
    acc = acc * t + p[k];
  return acc;
}

std::optional<Sign> certified(const Wide& v) {
  if (!v.decided()) return std::nullopt;
  return v.sign();
}

// The exact sign of p at the double t: the filter, then Horner in big numbers.
Sign sign_at_double(const Coeffs& p, const WideCoeffs& pw, double t) {
  if (const std::optional<Sign> s = certified(over(pw, t, t))) return *s;
  return sign_at(p, BigFloat(t));
}

// ---- isolation -------------------------------------------------------------------------------

// g(s) = p(lo + (hi - lo) s), then its Bernstein coefficients on [0, 1] times a positive
// integer constant (the lcm of the binomials C(n, k)): b_k C(n, k) = sum_{i <= k} C(n - i, k - i)
// g_i, integers times bounded values.
WideCoeffs scaled_bernstein(const WideCoeffs& p, double lo, double hi) {
  const int n = static_cast<int>(p.size()) - 1;
  const Wide base(lo), step = Wide(hi) - Wide(lo);
  WideCoeffs g{p.back()};
  for (int k = n - 1; k >= 0; --k) {
    WideCoeffs next(g.size() + 1);
    for (std::size_t i = 0; i < g.size(); ++i) {
      next[i] = next[i] + g[i] * base;
      next[i + 1] = next[i + 1] + g[i] * step;
    }
    next[0] = next[0] + p[static_cast<std::size_t>(k)];
    g = std::move(next);
  }
  std::vector<std::vector<std::int64_t>> c(static_cast<std::size_t>(n + 1));
  for (int r = 0; r <= n; ++r) {
    c[static_cast<std::size_t>(r)].assign(static_cast<std::size_t>(r + 1), 1);
    for (int k = 1; k < r; ++k) {
      c[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] =
          c[static_cast<std::size_t>(r - 1)][static_cast<std::size_t>(k - 1)] +
          c[static_cast<std::size_t>(r - 1)][static_cast<std::size_t>(k)];
    }
  }
  const auto choose = [&](int r, int k) {
    return c[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)];
  };
  std::int64_t lcm = 1;
  for (int k = 0; k <= n; ++k)
    lcm = std::lcm(lcm, choose(n, k));
  WideCoeffs b(static_cast<std::size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    Wide sum;
    for (int i = 0; i <= k; ++i) {
      sum = sum + Wide(static_cast<double>(choose(n - i, k - i))) * g[static_cast<std::size_t>(i)];
    }
    b[static_cast<std::size_t>(k)] = sum * Wide(static_cast<double>(lcm / choose(n, k)));
  }
  return b;
}

// The most sign variations the sequence can have when some signs are unknown (an unknown may
// be negative, zero or positive; zeros are skipped): dynamic programming over the last nonzero
// sign chosen.
int max_variations(const std::vector<std::optional<Sign>>& signs) {
  constexpr int kNone = -1000;
  int neg = kNone, pos = kNone, all_zero = 0;
  for (const std::optional<Sign>& s : signs) {
    const bool may_neg = !s || *s == Sign::negative, may_pos = !s || *s == Sign::positive;
    const bool may_zero = !s || *s == Sign::zero;
    int next_neg = may_zero ? neg : kNone, next_pos = may_zero ? pos : kNone;
    if (may_neg) next_neg = std::max({next_neg, all_zero, neg, pos + 1});
    if (may_pos) next_pos = std::max({next_pos, all_zero, pos, neg + 1});
    all_zero = may_zero ? all_zero : kNone;
    neg = next_neg;
    pos = next_pos;
  }
  return std::max({neg, pos, all_zero, 0});
}

// c(origin + width u) times a power of two, exactly: the Taylor shift (c(u + origin) by
// synthetic division, Knuth, TAOCP vol. 2, 4.6.4), then u^k scaled by width^k.
Coeffs moved(Coeffs c, const BigFloat& origin, const BigFloat& width) {
  const std::size_t n = c.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t k = n - 1; k-- > i;)
      c[k] = c[k] + origin * c[k + 1];
  }
  BigFloat power(1.0);
  for (std::size_t k = 1; k < n; ++k) {
    power = power * width;
    c[k] = c[k] * power;
  }
  trim(c);
  // A power of two scales every value alike (signs and roots kept): the largest coefficient
  // near 1, so that frames of narrow intervals (width^k far below 2^-16382) stay in long
  // double's range.
  std::int64_t top = std::numeric_limits<std::int64_t>::min();
  for (const BigFloat& x : c) {
    std::int64_t e = 0;
    if (x.frexp(e) != 0.0) top = std::max(top, e);
  }
  if (top != std::numeric_limits<std::int64_t>::min()) {
    for (BigFloat& x : c)
      x = x.scaled(-top);
  }
  return c;
}

// Where the isolation runs: t itself (level 0, the doubles of [lo, hi]; origin 0, width 1), or
// u in [0, 1] with t = origin + width u and the polynomial moved there exactly from the frame
// above (deeper levels, for roots closer than the doubles of the level above resolve: u's
// doubles resolve finely near u = 0, and the moved coefficients rounded describe p near its
// roots rather than at 0). A negative width reads the interval from its upper end, for roots
// hugging it, where u's doubles would be coarse.
struct Frame {
  const Coeffs& p;  // the polynomial in this frame's variable, exact
  const WideCoeffs& pw;
  BigFloat origin, width;
  double top = 1.0;                 // the frame's upper end in its variable
  double below = 0.0, above = 0.0;  // doubles enclosing the frame in t (levels >= 1)
  int level = 0;
  [[nodiscard]] BigFloat at(double u) const { return origin + width * BigFloat(u); }
  [[nodiscard]] bool reversed() const { return width.sign() == Sign::negative; }
};

// Levels of the isolation (each narrows an interval by 2^53 at least, or resolves a root
// hugging an end) and calls of `isolate` for one polynomial (uncertain signs may split many
// intervals): past them, the exact isolation answers. A budget, not a need: on hostile CCD
// queries (roots 2^-1300 apart, near-double roots) the filter spent up to 24 levels and 2048
// calls of Bernstein conversions before failing, most of a query's 5 ms (perf), where the exact
// Sturm isolation decides in about a millisecond; 8 levels still separate roots 2^-400 apart.
constexpr int kMaxLevels = 8;
constexpr int kMaxCalls = 256;

struct Isolation {
  const Coeffs& p;
  std::vector<RealRoot>& out;
  int max_levels = 0;
  int max_calls = 0;
  int calls = 0;
};

bool isolate(double a, double b_end, Sign s_a, Sign s_b, bool fresh, const Frame& frame,
             Isolation& iso);

// Isolation on [a, b_end] of the frame in a new frame over it, read from b_end when that is
// the frame's upper end (the interval's ends keep their signs).
bool isolate_deeper(double a, double b_end, Sign s_a, Sign s_b, const Frame& frame,
                    Isolation& iso) {
  if (frame.level + 1 >= iso.max_levels) return false;
  const bool flip = b_end == frame.top;
  const BigFloat start(flip ? b_end : a);
  const BigFloat step = flip ? BigFloat(a) - BigFloat(b_end) : BigFloat(b_end) - BigFloat(a);
  const Coeffs p = moved(frame.p, start, step);
  const std::optional<WideCoeffs> pw = to_wide(p);
  if (!pw) return false;
  const Frame deeper{p,
                     *pw,
                     frame.at(flip ? b_end : a),
                     frame.width * step,
                     1.0,
                     frame.level == 0 ? a : frame.below,
                     frame.level == 0 ? b_end : frame.above,
                     frame.level + 1};
  return flip ? isolate(0.0, 1.0, s_b, s_a, true, deeper, iso)
              : isolate(0.0, 1.0, s_a, s_b, true, deeper, iso);
}

void emit(double a, double b_end, Sign s_a, Sign s_b, const Frame& frame, Isolation& iso) {
  auto state = std::make_shared<RealRoot::State>();
  state->p = iso.p;
  const bool rev = frame.reversed();
  state->lo = frame.at(rev ? b_end : a);
  state->hi = frame.at(rev ? a : b_end);
  state->sign_lo = rev ? s_b : s_a;
  iso.out.emplace_back(std::move(state), frame.level == 0 ? a : frame.below,
                       frame.level == 0 ? b_end : frame.above, false);
}

// The roots in (a, b_end) (doubles of the frame's variable, end signs certified and nonzero),
// appended in increasing order of t; false when the bounds do not certify an isolation. Each
// interval gets its Bernstein coefficients from the frame's (so the split point may be any
// double: halving the doubles in between, which reaches roots near 0 in a few steps); an
// interval split from a bigger one whose coefficients no longer certify, or two adjacent
// doubles, goes to a deeper frame.
bool isolate(double a, double b_end, Sign s_a, Sign s_b, bool fresh, const Frame& frame,
             Isolation& iso) {
  if (++iso.calls > iso.max_calls) return false;
  const WideCoeffs b = scaled_bernstein(frame.pw, a, b_end);
  std::vector<std::optional<Sign>> signs{s_a};
  bool uncertain = false;
  for (std::size_t k = 1; k + 1 < b.size(); ++k) {
    signs.push_back(certified(b[k]));
    uncertain = uncertain || !signs.back();
  }
  signs.push_back(s_b);
  const int var = max_variations(signs);
  if (var == 0) return true;
  if (var == 1 && s_b == -s_a) {
    emit(a, b_end, s_a, s_b, frame, iso);
    return true;
  }
  const std::int64_t ka = order_key(a), kb = order_key(b_end);
  if (key_distance(ka, kb) < 2 || (uncertain && !fresh)) {
    return isolate_deeper(a, b_end, s_a, s_b, frame, iso);
  }
  const double mid = from_key(middle_key(ka, kb));
  const Sign s_mid = sign_at_double(frame.p, frame.pw, mid);
  if (s_mid == Sign::zero) return false;
  if (frame.reversed()) {
    return isolate(mid, b_end, s_mid, s_b, false, frame, iso) &&
           isolate(a, mid, s_a, s_mid, false, frame, iso);
  }
  return isolate(a, mid, s_a, s_mid, false, frame, iso) &&
         isolate(mid, b_end, s_mid, s_b, false, frame, iso);
}

// Divides c by (t - x) while x is a root; true when it was one.
bool divide_out(Coeffs& c, double x) {
  bool root = false;
  while (degree_of(c) >= 1 && sign_at(c, BigFloat(x)) == Sign::zero) {
    c = deflate(c, BigFloat(x));
    root = true;
  }
  return root;
}

RealRoot root_at(const Coeffs& p, double x) {
  auto state = std::make_shared<RealRoot::State>();
  state->p = p;
  state->lo = BigFloat(x);
  state->hi = state->lo;
  state->exact = true;
  return RealRoot(std::move(state), x, x, true);
}

// ---- signs at roots beyond double precision -----------------------------------------------

// Levels of refinement of a root below double spacing, once q is known not to vanish at the
// root (each narrows the bracket: by 2^53 when its bisection reaches two adjacent doubles of u).
constexpr int kLevels = 256;
// Bisection steps of a level that may take exact signs of p.
constexpr int kExactSteps = 4;

// Whether q vanishes at the root in (lo, hi) (exact ends, not roots of p): exactly when the root
// is one of g = gcd(p, q mod p)'s, that is when g changes sign on (lo, hi): g divides p, so its
// roots there are at most the root, simple. Cheaper than the Tarski query (no product P' q, so
// coefficients half as long), and asked only when the modular bound leaves a common root open.
bool vanishes_at_root(const Coeffs& q, const RealRoot::State& s, const BigFloat& lo,
                      const BigFloat& hi) {
  const Coeffs r = positive_pseudo_remainder(q, s.p);
  if (r.empty()) return true;
  const Coeffs g = gcd(s.p, r);
  return degree_of(g) >= 1 && sign_at(g, lo) != sign_at(g, hi);
}

// Newton's estimate of p's root in (ua, ub) (p of sign s0 at ua, the root simple) from the
// rounded coefficients, kept inside the bracket its own signs narrow (a step that leaves it is
// replaced by halving the bracket in the order of doubles, which reaches roots near 0 in a few
// steps). Only a guess: the caller certifies any bracket it derives.
double newton_estimate(const WideCoeffs& pw, double ua, double ub, Sign s0) {
  std::int64_t lo = order_key(ua), hi = order_key(ub);
  long double x = from_key(middle_key(lo, hi));
  for (int iteration = 0; iteration < 40 && key_distance(lo, hi) >= 2; ++iteration) {
    long double v = 0, d = 0;
    for (std::size_t k = pw.size(); k-- > 0;) {
      d = d * x + v;
      v = v * x + pw[k].value;
    }
    if (v == 0 || !std::isfinite(v) || !std::isfinite(d)) break;
    const std::int64_t kx = order_key(static_cast<double>(x));
    if ((v > 0) == (s0 == Sign::positive)) {
      lo = std::max(lo, kx);
    } else {
      hi = std::min(hi, kx);
    }
    const long double next = d != 0 ? x - v / d : x;
    if (next == x) break;
    // Compared in long double (a step far outside the doubles' range must not be narrowed).
    const bool inside = next > from_key(lo) && next < from_key(hi);
    x = inside ? next : from_key(middle_key(lo, hi));
  }
  return static_cast<double>(x);
}

// Narrows the bracket (a, b) (keys of doubles of u, p of sign s0 at a) to a few thousand doubles
// around Newton's estimate where p's certified signs at their ends prove the root between them:
// what some fifty bisection steps of a level find, in a few evaluations. The bracket is kept
// when no width certifies (the estimate off, or the root too close to a double for the filter).
// With `isolating` (lo, hi), p's other roots may lie in (a, b) outside (lo, hi): a new bracket
// must then lie within [lo, hi] as well.
void newton_narrow(const WideCoeffs& pw, std::int64_t& a, std::int64_t& b, Sign s0,
                   const RealRoot::State* isolating = nullptr) {
  if (key_distance(a, b) < 64) return;
  const std::int64_t x = order_key(newton_estimate(pw, from_key(a), from_key(b), s0));
  for (std::int64_t w = 4; w <= (std::int64_t{1} << 24); w *= 16) {
    const std::int64_t lo = x - w, hi = x + w;
    if (lo <= a || hi >= b) return;
    if (isolating != nullptr &&
        (BigFloat(from_key(lo)) < isolating->lo || isolating->hi < BigFloat(from_key(hi)))) {
      return;
    }
    const std::optional<Sign> at_lo = certified(over(pw, from_key(lo), from_key(lo)));
    const std::optional<Sign> at_hi = certified(over(pw, from_key(hi), from_key(hi)));
    if (at_lo == s0 && at_hi == -s0) {
      a = lo;
      b = hi;
      return;
    }
  }
}

// Records a narrower double bracket of the root (keys a < b of doubles strictly around it).
void learn_doubles(const RealRoot::State& s, std::int64_t a, std::int64_t b) {
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.learnt) {
    s.learnt = LearntBracket{a, b, nullptr};
  } else if (key_distance(a, b) < key_distance(s.learnt->below, s.learnt->above)) {
    s.learnt->below = a;
    s.learnt->above = b;
  }
}

// Records a refined frame when it resolves the root more finely than the one kept.
void learn_frame(const RealRoot::State& s, const LearntBracket::Frame& f) {
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.learnt) return;  // the double bracket is always learnt first
  const LearntBracket::Frame* kept = s.learnt->frame.get();
  if (kept != nullptr && (kept->level > f.level ||
                          (kept->level == f.level && key_distance(kept->u_below, kept->u_above) <=
                                                         key_distance(f.u_below, f.u_above)))) {
    return;
  }
  s.learnt->frame = std::make_shared<const LearntBracket::Frame>(f);
}

// The sign of q at the root in (lo, hi) (exact ends, p of sign sign_lo at lo, of the opposite
// sign at hi, one simple root between), the root closer to a double spacing than the filter
// over t resolved. p and q are moved to u in [0, 1] (t = lo + (hi - lo) u), exactly, so that
// the doubles of u resolve the root finely near u = 0 whatever its distance from t's doubles,
// and their coefficients rounded to long double describe the polynomials near the root rather
// than at 0; then the filter over t's doubles runs on u's. Each level moves them again onto the
// bracket of u left, once the bisection reaches two adjacent doubles or p's sign there is a close
// call past the first steps (read from its upper end when that is u = 1, where u's doubles are
// coarse). A query starts from the deepest frame an earlier query at the root learnt (q moved
// onto it in one Taylor shift), and leaves its own deepest frame for the next. Nothing when the
// levels run out: the caller's Tarski query answers.
std::optional<Sign> sign_on_refined(const Coeffs& q, const RealRoot::State& s, const BigFloat& lo,
                                    const BigFloat& hi) {
  std::shared_ptr<const LearntBracket::Frame> start;
  if (const std::optional<LearntBracket> learnt = s.learnt_bracket()) start = learnt->frame;
  LearntBracket::Frame f;
  if (start) {
    f = *start;
  } else {
    f.p = moved(s.p, lo, hi - lo);
    f.origin = lo;
    f.width = hi - lo;
    f.sign_at_0 = s.sign_lo;
    f.u_below = order_key(0.0);
    f.u_above = order_key(1.0);
  }
  Coeffs qu = moved(q, f.origin, f.width);
  for (int level = f.level; level < kLevels; ++level) {
    const std::optional<WideCoeffs> pw = to_wide(f.p), qw = to_wide(qu);
    if (!pw || !qw) return std::nullopt;
    std::int64_t& a = f.u_below;
    std::int64_t& b = f.u_above;
    for (int step = 0;; ++step) {
      // q's sign is asked at the start of a level, after Newton's jump and every few steps after
      // (rarely certified before the bracket is narrow: half the evaluations saved).
      const bool last = key_distance(a, b) < 2;
      if (step <= 1 || step % 4 == 0 || last) {
        if (const std::optional<Sign> v = certified(over(*qw, from_key(a), from_key(b)))) {
          learn_frame(s, f);
          return *v;
        }
      }
      if (last) break;
      if (step == 0) {
        newton_narrow(*pw, a, b, f.sign_at_0);
        continue;
      }
      const std::int64_t mk = middle_key(a, b);
      const double m = from_key(mk);
      // Once p's sign is a close call in this frame, the next frame is cheaper than exact
      // signs (the first steps take them, so that every level narrows the bracket).
      std::optional<Sign> sm = certified(over(*pw, m, m));
      if (!sm && step >= kExactSteps) break;
      if (!sm) sm = sign_at(f.p, BigFloat(m));
      if (*sm == Sign::zero) return sign_at_double(qu, *qw, m);  // the root is at u = m
      (*sm == f.sign_at_0 ? a : b) = mk;
    }
    const double ua = from_key(a), ub = from_key(b);
    const bool flip = ub == 1.0;
    const BigFloat origin(flip ? ub : ua);
    const BigFloat width = flip ? BigFloat(ua) - BigFloat(ub) : BigFloat(ub) - BigFloat(ua);
    f.p = moved(std::move(f.p), origin, width);
    qu = moved(std::move(qu), origin, width);
    f.origin = f.origin + f.width * origin;  // t = origin + width u, u = origin' + width' u'
    f.width = f.width * width;
    if (flip) f.sign_at_0 = -f.sign_at_0;
    f.u_below = order_key(0.0);
    f.u_above = order_key(1.0);
    f.level = level + 1;
  }
  learn_frame(s, f);
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<RealRoot>> filtered_real_roots(const Coeffs& p, double lo, double hi) {
  const int n = degree_of(p);
  if (!(lo < hi) || n < 1 || n > kMaxDegree) return std::nullopt;
  // Roots at the ends are divided out exactly, so that the isolation sees nonzero end signs.
  Coeffs inner = p;
  const bool root_lo = divide_out(inner, lo), root_hi = divide_out(inner, hi);
  std::vector<RealRoot> out;
  if (root_lo) out.push_back(root_at(p, lo));
  if (degree_of(inner) >= 1) {
    const std::optional<WideCoeffs> pw = to_wide(inner);
    if (!pw) return std::nullopt;
    const Sign s_lo = sign_at_double(inner, *pw, lo), s_hi = sign_at_double(inner, *pw, hi);
    // Deeper frames only for a squarefree p: roots of higher multiplicity never separate.
    // A multiple root never separates: the filter can only succeed where it lies outside
    // [lo, hi], which takes few calls (hostile CCD cubics with a double root in (0, 1) spent 57
    // calls failing before the exact isolation).
    const bool squarefree = gcd_degree_bound(inner, derivative(inner)) == 0;
    Isolation iso{inner, out, squarefree ? kMaxLevels : 1, squarefree ? kMaxCalls : kMaxCalls / 16};
    const Frame top{inner, *pw, BigFloat(), BigFloat(1.0), hi};
    if (!isolate(lo, hi, s_lo, s_hi, true, top, iso)) {
      return std::nullopt;
    }
  }
  if (root_hi) out.push_back(root_at(p, hi));
  return out;
}

std::optional<Sign> filtered_sign_at(const Coeffs& q, const RealRoot& root, bool refine) {
  const RealRoot::State& s = root.state();
  if (q.empty()) return Sign::zero;
  const std::optional<WideCoeffs> qw = to_wide(q), pw = to_wide(s.p);
  if (!qw || !pw) return std::nullopt;
  // From the narrowest double bracket an earlier query at this root left, if any.
  const std::optional<LearntBracket> learnt = s.learnt_bracket();
  std::int64_t a = learnt ? learnt->below : order_key(root.lower());
  std::int64_t b = learnt ? learnt->above : order_key(root.upper());
  // Newton's jump first (p's sign at any double of [s.lo, s.hi] below the root is sign_lo).
  newton_narrow(*pw, a, b, s.sign_lo, &s);
  for (;;) {
    if (const std::optional<Sign> v = certified(over(*qw, from_key(a), from_key(b)))) {
      learn_doubles(s, a, b);
      return *v;
    }
    if (key_distance(a, b) < 2) break;
    const std::int64_t mk = middle_key(a, b);
    const double m = from_key(mk);
    const BigFloat bm(m);
    bool below = false;  // m < the root
    if ((bm - s.lo).sign() != Sign::positive) {
      below = true;
    } else if ((bm - s.hi).sign() != Sign::negative) {
      below = false;
    } else {
      const Sign sm = sign_at_double(s.p, *pw, m);
      if (sm == Sign::zero) return sign_at(q, bm);  // the root is m
      below = sm == s.sign_lo;
    }
    (below ? a : b) = mk;
  }
  learn_doubles(s, a, b);
  if (!refine) return std::nullopt;
  const BigFloat lo = std::max(s.lo, BigFloat(from_key(a))),
                 hi = std::min(s.hi, BigFloat(from_key(b)));
  if (gcd_degree_bound(q, s.p) > 0 && vanishes_at_root(q, s, lo, hi)) return Sign::zero;
  return sign_on_refined(q, s, lo, hi);
}

Sign sign_at_double(const Coeffs& p, double t) {
  const std::optional<WideCoeffs> pw = to_wide(p);
  if (pw) return sign_at_double(p, *pw, t);
  return sign_at(p, BigFloat(t));
}

}  // namespace contain::predicates::detail
