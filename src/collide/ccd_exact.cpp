#include "collide/ccd_exact.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "contain/predicates/moving_points.h"
#include "contain/predicates/polynomial.h"

namespace contain::collide::detail {
namespace {

using predicates::Polynomial;
using predicates::RealRoot;

class ExactQuery {
 public:
  ExactQuery(const CcdQuery& q, PrimitivePair pair) : query_(q), pair_(pair) {
    const std::size_t count =
        pair == PrimitivePair::vertex_face ? kVertexFacePolys.size() : kEdgeEdgePolys.size();
    for (std::size_t k = 0; k < count; ++k) {
      rule_.push_back(
          build(pair == PrimitivePair::vertex_face ? kVertexFacePolys[k] : kEdgeEdgePolys[k]));
    }
  }

  [[nodiscard]] Polynomial build(const PolySpec& s) const {
    return predicates::exact_polynomial(query_, s);
  }

  // The rule at a time given as a root (or the double 0).
  template <class Time>
  [[nodiscard]] bool contact(const Time& t) const {
    return contact_rule(pair_, [&](int k) {
             return MaybeSign{sign_of(rule_[static_cast<std::size_t>(k)], t), true};
           }) == Tri::yes;
  }

  [[nodiscard]] const std::vector<Polynomial>& rule() const { return rule_; }

 private:
  static Sign sign_of(const Polynomial& p, double t) { return p.sign_at(t); }
  static Sign sign_of(const Polynomial& p, const RealRoot& r) { return predicates::sign_at(p, r); }

  const CcdQuery& query_;
  PrimitivePair pair_;
  std::vector<Polynomial> rule_;
};

Impact hit(double t) {
  return {true, t, CcdStage::exact};
}

}  // namespace

Impact exact_ccd(const CcdQuery& q, PrimitivePair pair) {
  const ExactQuery query(q, pair);
  const Polynomial f =
      query.build(pair == PrimitivePair::vertex_face ? kVertexFaceCubic : kEdgeEdgeCubic);
  if (!f.is_zero()) {
    // Contact needs coplanarity: the contact times are roots of the cubic.
    for (const RealRoot& root : predicates::real_roots(f, 0.0, 1.0)) {
      if (query.contact(root)) return hit(predicates::floor_to_double(root));
    }
    return {false, Impact{}.time, CcdStage::exact};
  }
  // Coplanar at every time: the contact set is closed, so its first point is 0 or a time where a
  // polynomial of the rule changes sign or vanishes (between such times every sign is constant).
  if (query.contact(0.0)) return hit(0.0);
  std::optional<double> best;
  for (const Polynomial& p : query.rule()) {
    if (p.is_zero()) continue;
    for (const RealRoot& root : predicates::real_roots(p, 0.0, 1.0)) {
      if (best && root.lower() >= *best) break;  // rounds no lower than the best so far
      if (!query.contact(root)) continue;
      const double t = predicates::floor_to_double(root);
      if (!best || t < *best) best = t;
      break;  // the later roots of p round no lower
    }
  }
  if (best) return hit(*best);
  return {false, Impact{}.time, CcdStage::exact};
}

}  // namespace contain::collide::detail
