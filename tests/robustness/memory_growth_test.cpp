// Memory grows as documented (docs/robustness.md, "Bad input" / "Memory and time"): readers and
// PolygonIndex are fed inputs of growing size and their peak heap use per element must stay
// under a stated bound, the same at every size; counts claimed by a header cost nothing until
// the bytes behind them are there.
//
// Heap use is measured by replacing the global operator new and delete in this test binary:
// every byte the library allocates through them is counted (glibc's malloc_usable_size, also
// provided by the sanitizers), and the peak above the level at the start of an operation is
// its peak extra memory.

#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numbers>
#include <string>
#include <vector>

#include "contain/inside/polygon_index.h"
#include "contain/inside/region_layer.h"
#include "contain/io/mesh_io.h"
#include "contain/io/points_io.h"
#include "contain/io/wkt.h"

namespace {

std::atomic<std::int64_t> g_current{0};
std::atomic<std::int64_t> g_peak{0};

void* counted(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  const auto now = g_current.fetch_add(static_cast<std::int64_t>(malloc_usable_size(p))) +
                   static_cast<std::int64_t>(malloc_usable_size(p));
  std::int64_t peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
  return p;
}

void uncounted(void* p) {
  if (p == nullptr) return;
  g_current.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)));
  std::free(p);
}

}  // namespace

void* operator new(std::size_t n) {
  return counted(std::malloc(n == 0 ? 1 : n));
}
void* operator new[](std::size_t n) {
  return counted(std::malloc(n == 0 ? 1 : n));
}
void* operator new(std::size_t n, std::align_val_t a) {
  const auto align = static_cast<std::size_t>(a);
  return counted(
      std::aligned_alloc(align, (std::max<std::size_t>(n, 1) + align - 1) / align * align));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return operator new(n, a);
}
void operator delete(void* p) noexcept {
  uncounted(p);
}
void operator delete[](void* p) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::size_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  uncounted(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  uncounted(p);
}

namespace contain {
namespace {

/// Runs `f` and returns the peak heap bytes it held above the level at its start.
template <class F>
std::int64_t peak_extra_bytes(F&& f) {
  const std::int64_t start = g_current.load();
  g_peak.store(start);
  f();
  return g_peak.load() - start;
}

// An n x n grid of quads, each split into two triangles: (n + 1)^2 vertices, 2 n^2 triangles.
Mesh grid_mesh(int n) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      mesh.vertices.push_back({i * 0.5, j * 0.25, (i * j) % 7 * 0.125});
  }
  auto at = [n](int i, int j) { return static_cast<std::int32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

// The stated bound (docs/robustness.md): reading a mesh holds at most this many bytes per
// triangle of the result at its peak (the mesh itself is about 12 bytes per triangle and 12 per
// triangle for its vertices, 24 bytes each, at two triangles per vertex), input bytes excluded.
constexpr double kMeshReaderBytesPerTriangle = 160.0;

TEST(MemoryGrowth, MeshReadersStayUnderTheirBytesPerTriangleAtEverySize) {
  for (const io::MeshFormat format :
       {io::MeshFormat::obj, io::MeshFormat::off, io::MeshFormat::stl_binary,
        io::MeshFormat::stl_ascii, io::MeshFormat::ply_ascii,
        io::MeshFormat::ply_binary_little_endian}) {
    for (const int n : {16, 64, 256}) {
      const Mesh mesh = grid_mesh(n);
      const std::string bytes = io::format_mesh(mesh, format);
      std::size_t triangles = 0;
      const std::int64_t peak = peak_extra_bytes([&] {
        auto file = io::parse_mesh(bytes, format, "grid");
        ASSERT_TRUE(file.ok()) << file.error().what();
        triangles = file->mesh.triangles.size();
      });
      ASSERT_EQ(triangles, mesh.triangles.size());
      const double per_triangle = static_cast<double>(peak) / static_cast<double>(triangles);
      EXPECT_LE(per_triangle, kMeshReaderBytesPerTriangle)
          << io::to_string(format) << ", n = " << n << ": " << peak << " bytes at the peak";
    }
  }
}

// Headers may claim any count; the readers reserve no more than the bytes present can hold.
TEST(MemoryGrowth, ClaimedCountsCostNothingUntilTheirBytesAreThere) {
  const std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 2000000000\n"
      "property list uchar int vertex_indices\nend_header\n" +
      std::string(64, '\0');
  const std::string off = "OFF\n2000000000 2000000000 0\n0 0 0\n1 0 0\n";
  std::string stl(80, ' ');
  stl += std::string("\xff\xff\xff\x7f", 4);  // 2^31 - 1 triangles claimed
  stl += std::string(100, '\0');
  for (const auto& input :
       {std::pair{ply, io::MeshFormat::ply_binary_little_endian},
        std::pair{off, io::MeshFormat::off}, std::pair{stl, io::MeshFormat::stl_binary}}) {
    const std::int64_t peak = peak_extra_bytes([&] {
      auto file = io::parse_mesh(input.first, input.second, "claims");
      EXPECT_FALSE(file.ok());
    });
    EXPECT_LE(peak, 64 * 1024) << io::to_string(input.second);
  }
}

// Point files: the points themselves (16 bytes each in 2D) plus the line numbers (8) and the
// flat table they are parsed into (16), with vector growth: at most 96 bytes a point.
constexpr double kPointsBytesPerPoint = 96.0;

TEST(MemoryGrowth, PointReaderStaysUnderItsBytesPerPointAtEverySize) {
  for (const int n : {1000, 10000, 100000}) {
    std::string text;
    for (int i = 0; i < n; ++i)
      text += std::to_string(i) + " " + std::to_string(i % 97) + ".5\n";
    const std::int64_t peak = peak_extra_bytes([&] {
      auto points = io::parse_points2(text, "points");
      ASSERT_TRUE(points.ok());
      ASSERT_EQ(points->points.size(), static_cast<std::size_t>(n));
    });
    EXPECT_LE(static_cast<double>(peak) / n, kPointsBytesPerPoint) << "n = " << n;
  }
}

// A star polygon of n edges whose spikes cross many cells.
Ring star(int n) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n;
    const double r = i % 2 == 0 ? 1.0 : 0.35;
    ring.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return ring;
}

// PolygonIndex (polygon_index.h): 4 bytes a cell and 32 per edge-cell pair, the grid coarsened
// until the pairs are at most 32 per edge (beyond min_cells), plus build scratch (the pair
// lists, 8 bytes a pair, with vector growth): measured ~80 bytes a pair at the peak, so at most
// 3 KiB per edge above a fixed 256 KiB. The star's long spikes are the hard case (before the
// coarsening: 34 KB per edge, 2.1 GB at 64,000 edges).
constexpr double kIndexBytesPerEdge = 3072.0;

TEST(MemoryGrowth, PolygonIndexStaysUnderItsBytesPerEdgeAtEverySize) {
  for (const int n : {1000, 8000, 64000}) {
    const std::vector<Ring> rings{star(n)};
    inside::PolygonIndex::Stats stats;
    const std::int64_t peak = peak_extra_bytes([&] {
      const inside::PolygonIndex index(rings);
      stats = index.stats();
    });
    EXPECT_LE(static_cast<double>(peak - 256 * 1024) / n, kIndexBytesPerEdge)
        << "n = " << n << ": " << peak << " bytes at the peak";
    std::printf("star of %d edges: %lld bytes at the peak, %zu cells, %zu edge-cell pairs\n", n,
                static_cast<long long>(peak), stats.cells, stats.edge_refs);
    // Edge-cell incidences grow linearly too.
    EXPECT_LE(stats.edge_refs, 48 * stats.edges) << "n = " << n;
  }
}

// RegionLayer (region_layer.h): per region a PolygonIndex capped at 16 cells an edge (one cell up
// to 8 edges) and its object, plus the tree over the boxes. Held (stats().bytes) and peak, per
// edge, for layers of many small regions (n x n squares: 4 edges a region, the per-region costs
// dominate) and of a few spiky ones.
constexpr double kLayerBytesPerEdgeHeld = 512.0;
constexpr double kLayerBytesPerEdgePeak = 1024.0;

TEST(MemoryGrowth, RegionLayerStaysUnderItsBytesPerEdgeAtEverySize) {
  for (const int n : {30, 60, 120}) {
    std::vector<MultiPolygon> regions;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        regions.push_back(MultiPolygon{{Polygon{
            {{{1.0 * i, 1.0 * j}, {i + 1.0, 1.0 * j}, {i + 1.0, j + 1.0}, {1.0 * i, j + 1.0}}}}}});
      }
    }
    inside::RegionLayer::Stats stats;
    const std::int64_t peak = peak_extra_bytes([&] {
      const inside::RegionLayer layer(regions);
      stats = layer.stats();
    });
    std::printf("%d squares: %zu edges, %zu bytes held, %lld at the peak\n", n * n, stats.edges,
                stats.bytes, static_cast<long long>(peak));
    EXPECT_LE(static_cast<double>(stats.bytes) / static_cast<double>(stats.edges),
              kLayerBytesPerEdgeHeld);
    EXPECT_LE(static_cast<double>(peak - 256 * 1024) / static_cast<double>(stats.edges),
              kLayerBytesPerEdgePeak);
  }
  for (const int n : {1000, 8000, 32000}) {
    std::vector<MultiPolygon> regions;
    for (int k = 0; k < 4; ++k)
      regions.push_back(MultiPolygon{{Polygon{{star(n / 4)}}}});
    inside::RegionLayer::Stats stats;
    const std::int64_t peak = peak_extra_bytes([&] {
      const inside::RegionLayer layer(regions);
      stats = layer.stats();
    });
    std::printf("4 stars of %d edges: %zu bytes held, %lld at the peak\n", n / 4, stats.bytes,
                static_cast<long long>(peak));
    EXPECT_LE(static_cast<double>(peak - 256 * 1024) / static_cast<double>(stats.edges),
              kIndexBytesPerEdge);
  }
}

}  // namespace
}  // namespace contain
