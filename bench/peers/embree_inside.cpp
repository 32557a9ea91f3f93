// Whole-process peer of `contain inside --mesh M.off --points PTS --threads 1`: reads the OFF
// and the points (peer_points.h), builds an Embree 3 scene (floats, one thread) and answers each
// point by ray parity (embree_parity.h: in or out, no "on"). Kernel times on stderr.
//   embree_inside MESH.off POINTS.txt > answers.txt

#include <cstdio>
#include <vector>

#include "bench/peers/embree_parity.h"
#include "bench/peers/peer_driver.h"
#include "bench/peers/peer_points.h"

int main(int argc, char** argv) {
  using namespace contain::bench;
  if (argc != 3) {
    std::fprintf(stderr, "usage: embree_inside MESH.off POINTS.txt\n");
    return 2;
  }
  const OffMesh mesh = read_off(argv[1]);
  const std::vector<double> xyz = read_numbers(argv[2]);
  const KernelClock build_clock;
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        mesh.vertices.size() / 3));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    v[i] = static_cast<float>(mesh.vertices[i]);
  auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size() / 3));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    f[i] = mesh.triangles[i];
  rtcSetGeometryIntersectFilterFunction(geometry, count_and_reject);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  build_clock.report("build");
  const KernelClock query_clock;
  std::vector<signed char> answers(xyz.size() / 3);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    answers[i] = odd_crossings(scene, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]) ? 1 : -1;
  }
  query_clock.report("query");
  write_answers(answers);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return 0;
}
