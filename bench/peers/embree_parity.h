#pragma once
// Embree 3 ray parity, the point-in-mesh answer of the Embree peers (point_in_mesh_bench,
// embree_inside): one rtcIntersect1 along +x whose filter counts every crossing and rejects it,
// so the ray runs to the end. Odd: inside. Floats, and no "on".

#include <embree3/rtcore.h>

#include <limits>

namespace contain::bench {

struct CountingContext {
  RTCIntersectContext context;
  int hits;
};

inline void count_and_reject(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<CountingContext*>(args->context);
  ++ctx->hits;
  args->valid[0] = 0;
}

// True when the ray from (x, y, z) along +x crosses the scene's triangles an odd number of times
// (their geometry has count_and_reject as its intersect filter).
[[nodiscard]] inline bool odd_crossings(RTCScene scene, double x, double y, double z) {
  CountingContext ctx{};
  rtcInitIntersectContext(&ctx.context);
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(x);
  rh.ray.org_y = static_cast<float>(y);
  rh.ray.org_z = static_cast<float>(z);
  rh.ray.dir_x = 1.0f;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx.context, &rh);
  return (ctx.hits & 1) != 0;
}

}  // namespace contain::bench
