#include "inside/csg_local.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace contain::inside::detail {
namespace {

// Outline (notation of csg.h). Every open region of a small ball about p, cut by the leaves'
// surfaces, contains a symbolic point
//     q = p + ε v + ε² (W / h + δ u1 + δ² u2),   0 < ε ≪ δ ≪ 1,
// where
// - v is a ray of the central arrangement of the constraint planes: ±(n_i × n_j) (rank 2 or 3),
//   or a direction in the common plane (rank 1). Every open cone of directions has such a ray
//   on its boundary (an extreme ray when the arrangement is pointed, the common line of rank 2),
//   and the cones next to v are the cells of what the constraints with n_i . v = 0 (the set Z)
//   do at second order;
// - for i not in Z the sign at q is sign(n_i . v) (first order);
// - for i in Z the sign is decided at ε²: a plane gives n_i . w, a ball of centre p + n_i gives
//   r² − |q − c|² = ε² (2 n_i . w − |v|²) + O(ε³), taking w ⊥ v (a component of w along v only
//   reparametrises ε). So in the plane normal to v each constraint of Z is a line a_i . w = b_i
//   (a = n, b = 0 for planes; a = 2 n, b = |v|² for balls), and the open regions near p + ε v
//   are the open cells of this affine line arrangement;
// - every cell of a line arrangement has on its boundary a vertex (two lines meet) or, when it
//   has none, a line without vertices. Sample points s = W / h: the origin, the foot of every
//   ball's line, every vertex. At s, for each line ℓ through s, u1 = ±(v × a_ℓ) runs along ℓ
//   and u2 = ±a_ℓ crosses it: the four symbolic points lie in the four wedges along ℓ, and
//   every wedge at s is bounded by some such ray. A constraint of Z through s takes the sign of
//   a . u1, or of a . u2 if that is zero (a ⊥ v, and u1, u2 span the plane ⊥ v, so one of them
//   is not zero); the others the sign of a . W − b h (h > 0).
// All quantities are polynomials in the input doubles, computed in exact dyadic arithmetic.
// Gap: where three second-order lines (two of them from balls) meet in one point, third-order
// terms may open a small cell there that no sample reaches.

struct Line {
  std::size_t constraint;
  BigVec3 a;
  BigFloat b;
};

class CsgSampler {
 public:
  CsgSampler(std::span<const LocalConstraint> constraints, const SolidContains& solid_contains)
      : constraints_(constraints),
        solid_contains_(solid_contains),
        positive_(constraints.size(), 0) {
    // Several leaves often share a surface at p (touching boxes, a box face on a half-space):
    // one representative per surface keeps the arrangement small.
    for (std::size_t i = 0; i < constraints.size(); ++i) {
      if (is_zero(constraints[i].normal)) {
        positive_[i] = constraints[i].fixed_value ? 1 : 0;
        continue;
      }
      const auto same = std::find_if(geometric_.begin(), geometric_.end(),
                                     [&](std::size_t r) { return same_surface(i, r); });
      if (same == geometric_.end()) {
        geometric_.push_back(i);
      } else {
        aliases_.emplace_back(i, *same);
      }
    }
  }

  Location run() {
    if (geometric_.empty()) {
      record({});
      return answer();
    }
    for (const BigVec3& v : rays()) {
      around_ray(v);
      if (seen_in_ && seen_out_) break;
    }
    return answer();
  }

 private:
  const BigVec3& n(std::size_t i) const { return constraints_[i].normal; }

  static bool same_direction(const BigVec3& a, const BigVec3& b) {
    return is_zero(cross(a, b)) && dot(a, b).sign() == Sign::positive;
  }

  // Two planes through p with the same inward direction, or two balls with the same centre.
  bool same_surface(std::size_t i, std::size_t j) const {
    if (constraints_[i].curved != constraints_[j].curved) return false;
    if (constraints_[i].curved) return is_zero(n(i) - n(j));
    return same_direction(n(i), n(j));
  }

  std::vector<BigVec3> rays() const {
    std::vector<BigVec3> out;
    for (std::size_t x = 0; x < geometric_.size(); ++x) {
      for (std::size_t y = x + 1; y < geometric_.size(); ++y) {
        BigVec3 v = cross(n(geometric_[x]), n(geometric_[y]));
        if (is_zero(v)) continue;
        const bool seen = std::any_of(out.begin(), out.end(),
                                      [&](const BigVec3& w) { return same_direction(v, w); });
        if (seen) continue;  // both v and -v are there already
        out.push_back(-v);
        out.push_back(std::move(v));
      }
    }
    if (out.empty()) {  // rank 1: all normals parallel; any direction in their common plane
      const BigVec3& m = n(geometric_.front());
      const BigVec3 axes[3] = {to_big(Vec3{1, 0, 0}), to_big(Vec3{0, 1, 0}), to_big(Vec3{0, 0, 1})};
      for (const BigVec3& e : axes) {
        BigVec3 v = cross(m, e);
        if (is_zero(v)) continue;
        out.push_back(-v);
        out.push_back(std::move(v));
        break;
      }
    }
    return out;
  }

  void around_ray(const BigVec3& v) {
    current_v_ = v;
    const BigFloat v2 = dot(v, v);
    std::vector<Line> lines;
    for (std::size_t i : geometric_) {
      const Sign s = dot(n(i), v).sign();
      if (s != Sign::zero) {
        positive_[i] = s == Sign::positive ? 1 : 0;
        continue;
      }
      const LocalConstraint& c = constraints_[i];
      if (c.curved) {
        lines.push_back({i, c.normal + c.normal, v2});
      } else {
        lines.push_back({i, c.normal, BigFloat()});
      }
    }
    // Sample points (W, h) with h > 0.
    at_point(lines, to_big(Vec3{}), BigFloat(1.0));
    for (const Line& l : lines) {
      if (!l.b.is_zero()) {
        // Foot of a ball's line: W = |v|² n, h = 2 |n|², so that 2 n . W = |v|² h.
        const BigVec3& m = n(l.constraint);
        at_point(lines, v2 * m, BigFloat(2.0) * dot(m, m));
      }
      if (seen_in_ && seen_out_) return;
    }
    for (std::size_t x = 0; x < lines.size(); ++x) {
      for (std::size_t y = x + 1; y < lines.size(); ++y) {
        // Cramer on rows a_x, a_y, v with right-hand side (b_x, b_y, 0).
        const BigVec3 ay_v = cross(lines[y].a, v);
        BigFloat h = dot(lines[x].a, ay_v);
        if (h.is_zero()) continue;  // parallel lines
        BigVec3 w = lines[x].b * ay_v + lines[y].b * cross(v, lines[x].a);
        if (h.sign() == Sign::negative) {
          h = -h;
          w = -w;
        }
        at_point(lines, w, h);
        if (seen_in_ && seen_out_) return;
      }
    }
  }

  void at_point(const std::vector<Line>& lines, const BigVec3& w, const BigFloat& h) {
    std::vector<std::size_t> through;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const Sign s = (dot(lines[k].a, w) - lines[k].b * h).sign();
      if (s == Sign::zero) {
        through.push_back(k);
      } else {
        positive_[lines[k].constraint] = s == Sign::positive ? 1 : 0;
      }
    }
    if (through.empty()) {
      record({&current_v_, &w});
      return;
    }
    std::vector<Sign> along(through.size()), across(through.size());
    for (std::size_t l : through) {
      const BigVec3 dir = cross(current_v_, lines[l].a);
      const BigVec3 u1[2] = {dir, -dir}, u2[2] = {lines[l].a, -lines[l].a};
      for (std::size_t k = 0; k < through.size(); ++k) {
        along[k] = dot(lines[through[k]].a, dir).sign();
        across[k] = dot(lines[through[k]].a, lines[l].a).sign();
      }
      for (int s1 : {1, -1}) {
        for (int s2 : {1, -1}) {
          for (std::size_t k = 0; k < through.size(); ++k) {
            const int first = s1 * to_int(along[k]);
            const int sign = first != 0 ? first : s2 * to_int(across[k]);
            positive_[lines[through[k]].constraint] = sign > 0 ? 1 : 0;
          }
          record({&current_v_, &w, &u1[s1 > 0 ? 0 : 1], &u2[s2 > 0 ? 0 : 1]});
          if (seen_in_ && seen_out_) return;
        }
      }
    }
  }

  void record(const SymbolicOffset& at) {
    for (const auto& [alias, representative] : aliases_)
      positive_[alias] = positive_[representative];
    if (solid_contains_(positive_, at)) {
      seen_in_ = true;
    } else {
      seen_out_ = true;
    }
  }

  Location answer() const {
    if (seen_in_ && seen_out_) return Location::boundary;
    return seen_in_ ? Location::inside : Location::outside;
  }

  std::span<const LocalConstraint> constraints_;
  const SolidContains& solid_contains_;
  std::vector<char> positive_;
  std::vector<std::size_t> geometric_;                        // one constraint per distinct surface
  std::vector<std::pair<std::size_t, std::size_t>> aliases_;  // (constraint, its representative)
  BigVec3 current_v_;
  bool seen_in_ = false;
  bool seen_out_ = false;
};

}  // namespace

Sign sign_at(const BigFloat& c, const BigVec3& g, const SymbolicOffset& at) {
  if (const Sign s = c.sign(); s != Sign::zero) return s;
  for (const BigVec3* term : {at.v, at.w, at.u1, at.u2}) {
    if (term == nullptr) continue;
    if (const Sign s = dot(g, *term).sign(); s != Sign::zero) return s;
  }
  return Sign::zero;
}

Location classify_neighbourhood(std::span<const LocalConstraint> constraints,
                                const SolidContains& solid_contains) {
  return CsgSampler(constraints, solid_contains).run();
}

}  // namespace contain::inside::detail
