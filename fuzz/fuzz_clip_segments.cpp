// libFuzzer target: segment clipping by boxes (2D and 3D) on random and degenerate segments
// (zero length, in a face, through a corner, parallel to a face) and boxes (flat, a point,
// empty). Claims checked:
// - Cohen-Sutherland, Liang-Barsky, Cyrus-Beck on the box's half-spaces and the batch kernel
//   agree on missed / touched / crossed, and with the exact GMP oracle;
// - a kept part lies in the closed box, 0 <= t0 <= t1 <= 1, an endpoint inside the box comes
//   back bit for bit, and a touching result is one point.
#include <array>
#include <cstdlib>
#include <span>

#include "clip/segment_oracle.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

void print(const char* name, Vec2 p) {
  std::fprintf(stderr, "%s (%a, %a)\n", name, p.x, p.y);
}
void print(const char* name, Vec3 p) {
  std::fprintf(stderr, "%s (%a, %a, %a)\n", name, p.x, p.y, p.z);
}

bool representable(const test::OracleClip& truth) {
  return !truth.touching && truth.t1 - truth.t0 > mpq_class(1, std::int64_t{1} << 40);
}

template <class Clipped, class Seg, class Box>
void check_result(const Clipped& r, const Seg& s, const Box& box, const test::OracleClip& truth) {
  if (std::getenv("FUZZ_VERBOSE") != nullptr) {
    print("segment a", s.a), print("segment b", s.b), print("box min", box.min);
    print("box max", box.max), print("kept a", r.segment.a), print("kept b", r.segment.b);
    std::fprintf(stderr, "kept %d t0 %a t1 %a; oracle kept %d touching %d\n", r.kept, r.t0, r.t1,
                 truth.kept, truth.touching);
  }
  FUZZ_CHECK(r.kept == truth.kept);
  if (!r.kept) return;
  FUZZ_CHECK(0.0 <= r.t0 && r.t0 <= r.t1 && r.t1 <= 1.0);
  if (box.contains(s.a)) FUZZ_CHECK(r.t0 == 0.0 && r.segment.a == s.a);
  if (box.contains(s.b)) FUZZ_CHECK(r.t1 == 1.0 && r.segment.b == s.b);
  if (truth.touching) {
    FUZZ_CHECK(r.t0 == r.t1 && r.segment.a == r.segment.b);
  } else {
    FUZZ_CHECK(box.contains(r.segment.a) && box.contains(r.segment.b));
  }
}

void fuzz2(fuzz::FuzzInput& in) {
  const Segment2 s{in.point2(), in.point2()};
  Box2 box;
  box.expand(in.point2());
  box.expand(in.point2());
  if (in.byte() % 16 == 0) std::swap(box.min.x, box.max.x);  // empty when min.x < max.x
  const test::OracleClip truth = test::oracle_clip(s, box);
  check_result(clip::cohen_sutherland(s, box), s, box, truth);
  check_result(clip::liang_barsky(s, box), s, box, truth);
  if (!box.empty()) {
    const std::array<HalfPlane, 4> sides{HalfPlane{1, 0, -box.min.x}, HalfPlane{-1, 0, box.max.x},
                                         HalfPlane{0, 1, -box.min.y}, HalfPlane{0, -1, box.max.y}};
    const clip::ClippedSegment2 cb = clip::cyrus_beck(s, sides);
    FUZZ_CHECK(cb.kept == truth.kept);
    if (cb.kept && box.contains(s.a)) FUZZ_CHECK(cb.t0 == 0.0 && cb.segment.a == s.a);
    if (cb.kept && box.contains(s.b)) FUZZ_CHECK(cb.t1 == 1.0 && cb.segment.b == s.b);
    // Cyrus-Beck's points are a + t (b - a) with rounded t: when the kept part is shorter than
    // the resolution of t (about 2^-53 of the segment) no double t names a point of it, so the
    // points are checked only where the part is longer (docs/robustness.md, "Fuzzing").
    if (cb.kept && representable(truth)) {
      FUZZ_CHECK(box.contains(cb.segment.a) && box.contains(cb.segment.b));
    }
  }
  std::array<Segment2, 1> out{};
  std::array<std::uint8_t, 1> kept{};
  clip::clip_segments(std::span(&s, 1), box, out, kept, {.threads = 1});
  FUZZ_CHECK((kept[0] != 0) == truth.kept);
  if (kept[0] != 0 && !truth.touching) FUZZ_CHECK(box.contains(out[0].a) && box.contains(out[0].b));
}

void fuzz3(fuzz::FuzzInput& in) {
  const Segment3 s{in.point3(), in.point3()};
  Box3 box;
  box.expand(in.point3());
  box.expand(in.point3());
  if (in.byte() % 16 == 0) std::swap(box.min.z, box.max.z);
  const test::OracleClip truth = test::oracle_clip(s, box);
  check_result(clip::cohen_sutherland(s, box), s, box, truth);
  check_result(clip::liang_barsky(s, box), s, box, truth);
  if (!box.empty()) {
    const std::array<Plane, 6> sides{Plane{1, 0, 0, -box.min.x}, Plane{-1, 0, 0, box.max.x},
                                     Plane{0, 1, 0, -box.min.y}, Plane{0, -1, 0, box.max.y},
                                     Plane{0, 0, 1, -box.min.z}, Plane{0, 0, -1, box.max.z}};
    const clip::ClippedSegment3 cb = clip::cyrus_beck(s, sides);
    FUZZ_CHECK(cb.kept == truth.kept);
    if (cb.kept && box.contains(s.a)) FUZZ_CHECK(cb.t0 == 0.0 && cb.segment.a == s.a);
    if (cb.kept && box.contains(s.b)) FUZZ_CHECK(cb.t1 == 1.0 && cb.segment.b == s.b);
    // Cyrus-Beck's points are a + t (b - a) with rounded t: when the kept part is shorter than
    // the resolution of t (about 2^-53 of the segment) no double t names a point of it, so the
    // points are checked only where the part is longer (docs/robustness.md, "Fuzzing").
    if (cb.kept && representable(truth)) {
      FUZZ_CHECK(box.contains(cb.segment.a) && box.contains(cb.segment.b));
    }
  }
  std::array<Segment3, 1> out{};
  std::array<std::uint8_t, 1> kept{};
  clip::clip_segments(std::span(&s, 1), box, out, kept, {.threads = 1});
  FUZZ_CHECK((kept[0] != 0) == truth.kept);
  if (kept[0] != 0 && !truth.touching) FUZZ_CHECK(box.contains(out[0].a) && box.contains(out[0].b));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  if (in.byte() % 2 == 0) {
    fuzz2(in);
  } else {
    fuzz3(in);
  }
  return 0;
}
