// PROVISIONAL floating-point body, replaced by the exact implementation in this same session.
#include "contain/predicates/cross_dot.h"
namespace contain::predicates {
Sign cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c) { return sign_of(dot(cross(b - a, p - a), cross(b - a, c - a))); }
}  // namespace contain::predicates
