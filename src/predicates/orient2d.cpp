// PROVISIONAL floating-point body, replaced by the exact implementation in this same session.
#include "contain/predicates/orient2d.h"
namespace contain::predicates {
Sign orient2d(Vec2 a, Vec2 b, Vec2 c) { return sign_of(cross(b - a, c - a)); }
}  // namespace contain::predicates
