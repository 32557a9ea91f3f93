#include "collide/ccd_filter.h"

#include <algorithm>

#include "contain/predicates/coplanarity_cubic.h"
#include "contain/predicates/cross_dot.h"
#include "contain/predicates/moving_points.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/polynomial.h"

namespace contain::collide::detail {
namespace {

using predicates::CoplanarityCubic;
using predicates::IntervalSigns;
using predicates::RootBracket;

// The swept boxes of the two primitives (each point's path lies in the box of its ends) are
// disjoint: exact comparisons of input doubles.
bool swept_boxes_disjoint(const CcdQuery& q, int first_of_b) {
  for (int c = 0; c < 3; ++c) {
    const auto at = [&](int i) {
      const Vec3& v = q[static_cast<std::size_t>(i)];
      return c == 0 ? v.x : (c == 1 ? v.y : v.z);
    };
    double lo_a = at(0), hi_a = at(0), lo_b = at(first_of_b), hi_b = at(first_of_b);
    for (int i = 0; i < 4; ++i) {
      for (const int k : {i, i + 4}) {
        const double x = at(k);
        if (i < first_of_b) {
          lo_a = std::min(lo_a, x);
          hi_a = std::max(hi_a, x);
        } else {
          lo_b = std::min(lo_b, x);
          hi_b = std::max(hi_b, x);
        }
      }
    }
    if (hi_a < lo_b || hi_b < lo_a) return true;
  }
  return false;
}

Tri contact_over(const CcdQuery& q, PrimitivePair pair, double lo, double hi) {
  IntervalSigns signs(q, lo, hi);
  const auto& polys = pair == PrimitivePair::vertex_face
                          ? std::span<const PolySpec>(kVertexFacePolys)
                          : std::span<const PolySpec>(kEdgeEdgePolys);
  return contact_rule(pair, [&](int k) {
    const std::optional<Sign> s = signs.sign(polys[static_cast<std::size_t>(k)]);
    return s ? MaybeSign{*s, true} : MaybeSign{Sign::zero, false};
  });
}

// The rule at a double time, always decided: the filter first, then each sign it leaves open
// exactly (at t = 0 and t = 1 the positions are the input doubles and cross_dot is the
// `cross_dot` predicate; otherwise, and for dot, the exact polynomial's sign at t).
bool contact_at(const CcdQuery& q, PrimitivePair pair, double t) {
  IntervalSigns signs(q, t, t);
  const auto& polys = pair == PrimitivePair::vertex_face
                          ? std::span<const PolySpec>(kVertexFacePolys)
                          : std::span<const PolySpec>(kEdgeEdgePolys);
  return contact_rule(pair, [&](int k) {
           const PolySpec& p = polys[static_cast<std::size_t>(k)];
           if (const std::optional<Sign> s = signs.sign(p)) return MaybeSign{*s, true};
           if (p.kind == MotionKind::cross_dot && (t == 0.0 || t == 1.0)) {
             const std::size_t base = t == 0.0 ? 0 : 4;
             const auto at = [&](int i) { return q[base + static_cast<std::size_t>(i)]; };
             return MaybeSign{predicates::cross_dot(at(p.i), at(p.j), at(p.k), at(p.l)), true};
           }
           return MaybeSign{predicates::exact_polynomial(q, p).sign_at(t), true};
         }) == Tri::yes;
}

// The rule at a root of the cubic: the filter over its bracket first, each sign it leaves open
// exactly at the root.
Tri contact_at_root(const CcdQuery& q, PrimitivePair pair, const RootBracket& b,
                    const predicates::RealRoot& root) {
  IntervalSigns signs(q, b.lo, b.hi);
  const auto& polys = pair == PrimitivePair::vertex_face
                          ? std::span<const PolySpec>(kVertexFacePolys)
                          : std::span<const PolySpec>(kEdgeEdgePolys);
  return contact_rule(pair, [&](int k) {
    const PolySpec& p = polys[static_cast<std::size_t>(k)];
    if (const std::optional<Sign> s = signs.sign(p)) return MaybeSign{*s, true};
    return MaybeSign{predicates::sign_at(predicates::exact_polynomial(q, p), root), true};
  });
}

}  // namespace

std::optional<Impact> filtered_ccd(const CcdQuery& q, PrimitivePair pair) {
  const bool vf = pair == PrimitivePair::vertex_face;
  if (swept_boxes_disjoint(q, vf ? 1 : 2)) return Impact{false, Impact{}.time, CcdStage::boxes};
  const PolySpec spec = vf ? kVertexFaceCubic : kEdgeEdgeCubic;
  const CoplanarityCubic f(q, spec);
  if (f.sign_on_unit()) return Impact{false, Impact{}.time, CcdStage::coplanarity};
  const auto at = [&](int i, int time) { return q[static_cast<std::size_t>(i + 4 * time)]; };
  const Sign at0 = predicates::orient3d(at(spec.i, 0), at(spec.j, 0), at(spec.k, 0), at(spec.l, 0));
  // No relative motion (every point moved by the same vector): the configuration at t = 0 holds
  // at every time, so the answer is the static test: coplanar at 0 and the inclusion rule.
  if (predicates::rigidly_translating(q)) {
    return at0 == Sign::zero && contact_at(q, pair, 0.0)
               ? Impact{true, 0.0, CcdStage::filter}
               : Impact{false, Impact{}.time, CcdStage::filter};
  }
  const Sign at1 = predicates::orient3d(at(spec.i, 1), at(spec.j, 1), at(spec.k, 1), at(spec.l, 1));
  if (at0 == Sign::zero && contact_at(q, pair, 0.0)) return Impact{true, 0.0, CcdStage::filter};
  const std::optional<predicates::RootBrackets> roots = f.roots_in_open_unit(at0, at1);
  if (!roots) return std::nullopt;
  CcdStage stage = CcdStage::filter;
  for (int r = 0; r < roots->count; ++r) {
    // Decide the inclusion on a bracket of width 2^-10 first (a few certified Newton steps),
    // then, if that is too wide, on the narrowest bracket doubles allow.
    RootBracket b = f.narrow(roots->brackets[static_cast<std::size_t>(r)], 0x1p-10);
    Tri c = contact_over(q, pair, b.lo, b.hi);
    if (c == Tri::unknown) {
      b = f.narrow(b);
      c = contact_over(q, pair, b.lo, b.hi);
    }
    if (c == Tri::unknown) {
      // A sign the rule needs is (nearly) zero at the root, as where a vertex meets an edge: the
      // certified bracket isolates the root, so only that sign goes to the exact stage.
      const predicates::RealRoot root =
          predicates::root_between(predicates::exact_polynomial(q, spec), b.lo, b.hi);
      c = contact_at_root(q, pair, b, root);
      stage = CcdStage::exact;
    }
    if (c == Tri::no) continue;
    b = f.narrow(b);
    return Impact{true, f.floor(b), stage};
  }
  if (at1 == Sign::zero && contact_at(q, pair, 1.0)) return Impact{true, 1.0, stage};
  return Impact{false, Impact{}.time, stage};
}

}  // namespace contain::collide::detail
