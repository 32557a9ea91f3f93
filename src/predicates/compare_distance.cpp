// PROVISIONAL floating-point body, replaced by the exact implementation in this same session.
#include "contain/predicates/compare_distance.h"
namespace contain::predicates {
Sign side_of_sphere(const Sphere& s, Vec3 p) { return sign_of(s.radius * s.radius - squared_length(p - s.center)); }
Sign side_of_circle(const Circle& s, Vec2 p) { return sign_of(s.radius * s.radius - squared_length(p - s.center)); }
}  // namespace contain::predicates
