// Sections of a closed mesh by many parallel planes: contain's kernel in its two parts beside
// Manifold's, in one run, and beside CGAL's slicer.
//   sphere131k, sphere524k   UV spheres of radius 1 (256 x 256 and 512 x 512 quads, poles as
//                            fans: 130,560 and 523,264 triangles), built in this file; any mesh
//                            files given on the command line after them (OFF, OBJ, ...);
//   N planes                 the middles of N equal layers of the mesh's z extent (for the
//                            spheres z = -1 + (k + 0.5) 2 / N: no plane through a vertex).
// The kernels, one thread, each part timed alone (median of --reps runs, contain and Manifold
// alternating so that load swings hit both):
//   prepare  contain: clip::MeshSlicer::make (closedness check, weld, pairing of half-edges,
//            triangles filed by the first plane they reach); Manifold: its solid built from a
//            MeshGL64 (half-edge structure, collider), the counterpart its Slice needs.
//   slice    contain: slicer.slice(0, N) (exact filled regions with holes, provenance per edge);
//            Manifold: N calls of Manifold::Slice (raw contours: no nesting, no fill, rounded
//            crossing decisions).
// The conversion of contain's Mesh to Manifold's MeshGL64 is not timed. Then, as before, the
// whole clip::slice_mesh call on one thread and on every core, and CGAL 5.5 Polygon_mesh_slicer
// (polylines only, its AABB tree built inside the timed part, one call per plane) for 100 and
// 10,000 planes. Checked outside the timed parts: contain's areas on the spheres sum to within
// 1e-3 of the exact sphere's sum of pi (1 - z^2) (the mesh is inscribed), and the number of
// rings of contain and of contours of Manifold and CGAL per plane is printed. Times: CPU seconds
// (process; one thread except the all-cores row) and wall seconds for the whole calls: the
// 2-core machine is shared, CPU time is the measure.
// Usage: slice_bench [--reps R] [--planes N] [--quick] [MESH ...]
//   --reps R    runs of each kernel part (default 5); --planes N (default 100) for the parts;
//   --quick     the parts only (no whole-call rows, no 10,000 planes, no CGAL).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "contain/clip/mesh_slicer.h"
#include "contain/clip/slice_mesh.h"
#include "contain/io/mesh_io.h"

#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>
#endif

#ifdef CONTAIN_BENCH_HAS_MANIFOLD
#include <manifold/manifold.h>
#endif

namespace {

using namespace contain;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Scene {
  std::string name;
  Mesh mesh;
  bool sphere = false;  // a unit sphere: areas checked against the exact ones
};

// The middles of n equal layers of the mesh's z extent.
std::vector<double> planes(const Mesh& mesh, int n) {
  double lo = INFINITY;
  double hi = -INFINITY;
  for (const Vec3& p : mesh.vertices) {
    lo = std::min(lo, p.z);
    hi = std::max(hi, p.z);
  }
  std::vector<double> out;
  for (int k = 0; k < n; ++k)
    out.push_back(lo + (hi - lo) * (k + 0.5) / n);
  return out;
}

// The median, least and greatest of a part's runs.
struct Spread {
  double median = 0;
  double min = 0;
  double max = 0;
};
Spread spread(std::vector<double> runs) {
  std::sort(runs.begin(), runs.end());
  return {runs[runs.size() / 2], runs.front(), runs.back()};
}

// One run of both parts: CPU seconds, and the rings (contain) or contours (Manifold) counted.
struct Parts {
  double prepare = 0;
  double slice = 0;
  std::size_t rings = 0;
};

Parts contain_parts(const Mesh& mesh, const std::vector<double>& values) {
  Parts out;
  const double c0 = cpu_seconds();
  auto slicer = clip::MeshSlicer::make(mesh, values);
  const double c1 = cpu_seconds();
  if (!slicer) {
    std::printf("contain refuses the mesh: %s\n", slicer.error().what().c_str());
    std::exit(1);
  }
  const std::vector<clip::Section> sections = slicer->slice(0, values.size(), {.threads = 1});
  const double c2 = cpu_seconds();
  out.prepare = c1 - c0;
  out.slice = c2 - c1;
  for (const clip::Section& s : sections)
    out.rings += s.triangles.size();
  return out;
}

#ifdef CONTAIN_BENCH_HAS_MANIFOLD
manifold::MeshGL64 to_manifold(const Mesh& mesh) {
  manifold::MeshGL64 out;
  out.numProp = 3;
  for (const Vec3& v : mesh.vertices)
    out.vertProperties.insert(out.vertProperties.end(), {v.x, v.y, v.z});
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::int32_t v : t)
      out.triVerts.push_back(static_cast<std::uint64_t>(v));
  }
  return out;
}

Parts manifold_parts(const manifold::MeshGL64& mesh, const std::vector<double>& values) {
  Parts out;
  const double c0 = cpu_seconds();
  const manifold::Manifold solid(mesh);
  const bool ok = solid.Status() == manifold::Manifold::Error::NoError;
  const double c1 = cpu_seconds();
  if (!ok) {
    std::printf("Manifold refuses the mesh: error %d\n", static_cast<int>(solid.Status()));
    std::exit(1);
  }
  std::vector<manifold::Polygons> sections;
  sections.reserve(values.size());
  for (const double value : values)
    sections.push_back(solid.Slice(value));
  const double c2 = cpu_seconds();
  out.prepare = c1 - c0;
  out.slice = c2 - c1;
  for (const manifold::Polygons& p : sections)
    out.rings += p.size();
  return out;
}
#endif

void print_part(const Scene& s, std::size_t n, const char* part, const char* who, const Spread& t,
                std::size_t rings) {
  std::printf("%-17s %6zu planes  %-8s %-9s cpu %8.4f s  (min %.4f, max %.4f)  rings %zu\n",
              s.name.c_str(), n, part, who, t.median, t.min, t.max, rings);
}

// contain's two parts beside Manifold's, `reps` runs each, alternating; the ratios of medians.
void run_parts(const Scene& s, int n, int reps) {
  const std::vector<double> values = planes(s.mesh, n);
  std::vector<double> prepare, slice;
  Parts last;
#ifdef CONTAIN_BENCH_HAS_MANIFOLD
  const manifold::MeshGL64 gl = to_manifold(s.mesh);
  std::vector<double> build, cut;
  Parts peer;
#endif
  for (int r = 0; r < reps; ++r) {
    last = contain_parts(s.mesh, values);
    prepare.push_back(last.prepare);
    slice.push_back(last.slice);
#ifdef CONTAIN_BENCH_HAS_MANIFOLD
    peer = manifold_parts(gl, values);
    build.push_back(peer.prepare);
    cut.push_back(peer.slice);
#endif
  }
  const Spread p = spread(prepare);
  const Spread c = spread(slice);
  print_part(s, values.size(), "prepare", "contain", p, last.rings);
  print_part(s, values.size(), "slice", "contain", c, last.rings);
#ifdef CONTAIN_BENCH_HAS_MANIFOLD
  const Spread pb = spread(build);
  const Spread pc = spread(cut);
  print_part(s, values.size(), "prepare", "Manifold", pb, peer.rings);
  print_part(s, values.size(), "slice", "Manifold", pc, peer.rings);
  std::printf(
      "%-17s %6zu planes  contain / Manifold (medians): prepare %.3f  slice %.3f  both %.3f\n",
      s.name.c_str(), values.size(), p.median / pb.median, c.median / pc.median,
      (p.median + c.median) / (pb.median + pc.median));
#else
  std::printf("%-17s Manifold not built in (configure with CONTAIN_MANIFOLD_DIR)\n",
              s.name.c_str());
#endif
}

void run_contain(const Scene& s, const std::vector<double>& values, int threads) {
  const double c0 = cpu_seconds();
  const double w0 = wall_seconds();
  auto sections = clip::slice_mesh(s.mesh, values, {}, {.threads = threads});
  const double cpu = cpu_seconds() - c0;
  const double wall = wall_seconds() - w0;
  if (!sections) {
    std::printf("%s: %s\n", s.name.c_str(), sections.error().what().c_str());
    return;
  }
  std::size_t single = 0;
  double area = 0;
  double exact = 0;
  for (const clip::Section& section : *sections) {
    const std::vector<Ring> rings = section.region.all_rings();
    single += rings.size() == 1 ? 1 : 0;
    for (const Ring& r : rings)
      area += signed_area2(r) / 2;
    exact += std::numbers::pi * (1 - section.value * section.value);
  }
  std::printf("%-17s %6zu planes  contain %-10s cpu %7.3f s  wall %7.3f s  one ring: %zu/%zu",
              s.name.c_str(), values.size(), threads == 1 ? "1 thread" : "all cores", cpu, wall,
              single, values.size());
  if (s.sphere) std::printf("  area/exact %.6f", area / exact);
  std::printf("\n");
}

#ifdef CONTAIN_BENCH_HAS_CGAL
void run_cgal(const Scene& s, const std::vector<double>& values) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  for (const Vec3& p : s.mesh.vertices)
    v.push_back(sm.add_vertex(K::Point_3(p.x, p.y, p.z)));
  for (const TriangleIndices& t : s.mesh.triangles)
    sm.add_face(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                v[static_cast<std::size_t>(t[2])]);
  const double c0 = cpu_seconds();
  const double w0 = wall_seconds();
  CGAL::Polygon_mesh_slicer<SurfaceMesh, K> slicer(sm);
  std::vector<std::vector<std::vector<K::Point_3>>> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    slicer(K::Plane_3(0, 0, 1, -values[i]), std::back_inserter(out[i]));
  const double cpu = cpu_seconds() - c0;
  const double wall = wall_seconds() - w0;
  std::size_t single = 0;
  for (const auto& polylines : out)
    single += polylines.size() == 1 ? 1 : 0;
  std::printf(
      "%-17s %6zu planes  CGAL slicer          cpu %7.3f s  wall %7.3f s  one polyline: "
      "%zu/%zu\n",
      s.name.c_str(), values.size(), cpu, wall, single, values.size());
}
#endif

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  int n = 100;
  bool quick = false;
  std::vector<Scene> scenes;
  scenes.push_back({"sphere131k", scenes::uv_sphere({0, 0, 0}, 1.0, 256, 256), true});
  scenes.push_back({"sphere524k", scenes::uv_sphere({0, 0, 0}, 1.0, 512, 512), true});
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if ((arg == "--reps" || arg == "--planes") && i + 1 < argc) {
      (arg == "--reps" ? reps : n) = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--quick") {
      quick = true;
    } else {
      Result<io::MeshFile> file = io::read_mesh(std::string(arg));
      if (!file) {
        std::fprintf(stderr, "%s\n", file.error().what().c_str());
        return 2;
      }
      const std::string path(arg);
      scenes.push_back({path.substr(path.find_last_of('/') + 1), std::move(file->mesh), false});
    }
  }
  for (const Scene& s : scenes)
    run_parts(s, n, reps);
  if (quick) return 0;
  for (const Scene& s : scenes) {
    for (const int count : {100, 10000}) {
      const std::vector<double> values = planes(s.mesh, count);
      run_contain(s, values, 1);
      run_contain(s, values, 0);
#ifdef CONTAIN_BENCH_HAS_CGAL
      run_cgal(s, values);
#endif
    }
  }
  return 0;
}
