// PROVISIONAL floating-point body, replaced by the exact implementation in this same session.
#include "contain/predicates/orient3d.h"
namespace contain::predicates {
Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return sign_of(dot(cross(b - a, c - a), d - a)); }
}  // namespace contain::predicates
