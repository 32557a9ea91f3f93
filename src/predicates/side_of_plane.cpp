// PROVISIONAL floating-point body, replaced by the exact implementation in this same session.
#include "contain/predicates/side_of_plane.h"
namespace contain::predicates {
Sign side_of_plane(const Plane& h, Vec3 p) { return sign_of(h.a * p.x + h.b * p.y + h.c * p.z + h.d); }
Sign side_of_line(const HalfPlane& h, Vec2 p) { return sign_of(h.a * p.x + h.b * p.y + h.c); }
}  // namespace contain::predicates
