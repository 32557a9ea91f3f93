#include "contain/inside/index_file.h"
#include "contain/bound/aabb.h"

#include <gtest/gtest.h>
#include <span>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "inside/mesh_test_meshes.h"
#include "inside/polygon_random.h"
#include "scenes/scenes.h"

namespace contain::inside {
namespace {

// Random points in a box grown by a quarter on each side, plus the degenerate ones: every
// vertex, every edge's midpoint, the points of a coarse lattice (on grid planes and faces).
std::vector<Vec3> probes(const Mesh& mesh, std::size_t count, std::uint64_t seed) {
  const Box3 box = bound::aabb(std::span<const Vec3>(mesh.vertices));
  const Vec3 grow = 0.25 * (box.max - box.min);
  std::vector<Vec3> points =
      scenes::uniform_points(Box3{box.min - grow, box.max + grow}, count, seed);
  points.insert(points.end(), mesh.vertices.begin(), mesh.vertices.end());
  for (const TriangleIndices& t : mesh.triangles) {
    points.push_back(0.5 * mesh.vertex(t[0]) + 0.5 * mesh.vertex(t[1]));
    points.push_back((1.0 / 3.0) * (mesh.vertex(t[0]) + mesh.vertex(t[1]) + mesh.vertex(t[2])));
  }
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j)
      for (int k = 0; k <= 8; ++k)
        points.push_back(box.min + Vec3{i / 8.0 * (box.max.x - box.min.x),
                                        j / 8.0 * (box.max.y - box.min.y),
                                        k / 8.0 * (box.max.z - box.min.z)});
  return points;
}

void expect_same_answers(const MeshIndex& fresh, const MeshIndex& loaded,
                         const std::vector<Vec3>& points) {
  EXPECT_EQ(loaded.regime(), fresh.regime());
  EXPECT_EQ(loaded.report().closed(), fresh.report().closed());
  EXPECT_EQ(loaded.report().edges, fresh.report().edges);
  EXPECT_EQ(loaded.report().genus, fresh.report().genus);
  EXPECT_EQ(loaded.report().signed_volume, fresh.report().signed_volume);
  EXPECT_EQ(loaded.bounds().min, fresh.bounds().min);
  EXPECT_EQ(loaded.bounds().max, fresh.bounds().max);
  EXPECT_EQ(loaded.stats().cells, fresh.stats().cells);
  EXPECT_EQ(loaded.stats().cell_refs, fresh.stats().cell_refs);
  std::vector<Location> a(points.size()), b(points.size());
  fresh.locate(points, a, {.threads = 1});
  loaded.locate(points, b, {.threads = 1});
  EXPECT_EQ(a, b);
  for (std::size_t i = 0; i < points.size(); i += 7)
    ASSERT_EQ(loaded.locate(points[i]), a[i]) << i;
}

MeshIndex round_trip(const MeshIndex& index) {
  auto loaded = parse_mesh_index(format_index(index));
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().what());
  return loaded.ok() ? std::move(loaded).value() : MeshIndex{};
}

// The header's two checksums made right again after a payload change: the file then reaches
// the payload's own checks (a crafted file, not a damaged one).
void reseal(std::vector<std::byte>& bytes) {
  const auto payload = std::span<const std::byte>(bytes).subspan(index_header_size);
  const std::uint64_t sum = index_checksum(payload);
  std::memcpy(bytes.data() + 40, &sum, 8);
  const std::uint64_t head = index_checksum(std::span<const std::byte>(bytes).first(56));
  std::memcpy(bytes.data() + 56, &head, 8);
}

TEST(MeshIndexFile, LoadedClosedMeshesAnswerExactlyAsFresh) {
  for (const Mesh& mesh : {test::grid_cube(-1, 1, 3), test::l_prism(), test::octahedron(2.0),
                           scenes::torus(1.0, 0.4, 24, 12)}) {
    const MeshIndex fresh(mesh);
    ASSERT_EQ(fresh.regime(), MeshRegime::closed_exact);
    expect_same_answers(fresh, round_trip(fresh), probes(mesh, 3000, 7));
  }
}

TEST(MeshIndexFile, LoadedSolidsKeepTheirWindingNumbersParityAndGridlessIndexes) {
  // Overlapping cubes (winding number 2 in the overlap, kept in the empty cells), the same with
  // an inverted third cube, a cube with one triangle flipped (ray parity), and an index built
  // for few queries (no grid).
  Mesh overlap = test::grid_cube(0, 2, 1);
  Mesh other = test::grid_cube(1, 3, 1);
  const auto shift = static_cast<std::int32_t>(overlap.vertices.size());
  overlap.vertices.insert(overlap.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (TriangleIndices t : other.triangles)
    overlap.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  Mesh hollow = overlap;
  Mesh inner = test::grid_cube(0.5, 1.5, 1);
  const auto at = static_cast<std::int32_t>(hollow.vertices.size());
  hollow.vertices.insert(hollow.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (TriangleIndices t : inner.triangles)
    hollow.triangles.push_back({t[0] + at, t[2] + at, t[1] + at});
  Mesh flipped = test::grid_cube(0, 2, 2);
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  for (const Mesh& mesh : {overlap, hollow, flipped}) {
    for (const std::size_t queries : {std::size_t{0}, std::size_t{1}}) {
      const MeshIndex fresh(mesh, {.queries = queries});
      ASSERT_EQ(fresh.regime(), MeshRegime::closed_exact);
      expect_same_answers(fresh, round_trip(fresh), probes(mesh, 1500, 9));
    }
  }
  EXPECT_EQ(round_trip(MeshIndex(overlap)).locate({1.5, 1.5, 1.5}), Location::inside);
}

TEST(MeshIndexFile, LoadedOpenMeshAnswersExactlyAsFreshWithItsWindingAccuracy) {
  Mesh open = test::grid_cube(0, 1, 2);
  open.triangles.pop_back();  // a hole: the winding number regime
  for (double accuracy : {2.0, 3.0}) {
    const MeshIndex fresh(open, {.winding_accuracy = accuracy});
    ASSERT_EQ(fresh.regime(), MeshRegime::winding_number);
    expect_same_answers(fresh, round_trip(fresh), probes(open, 2000, 8));
  }
}

TEST(MeshIndexFile, EmptyMeshRoundTripsToAnIndexWithNothingInside) {
  const MeshIndex empty{Mesh{}};
  const MeshIndex loaded = round_trip(empty);
  EXPECT_EQ(loaded.locate(Vec3{0, 0, 0}), Location::outside);
  EXPECT_EQ(loaded.stats().triangles, 0u);
}

TEST(MeshIndexFile, FingerprintIsTheTrianglesWhateverTheirOrderOrUnusedVertices) {
  const Mesh mesh = test::l_prism();
  Mesh shuffled = mesh;
  std::mt19937_64 rng(3);
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
  shuffled.vertices.push_back({9, 9, 9});  // used by no triangle
  EXPECT_EQ(fingerprint(shuffled), fingerprint(mesh));
  EXPECT_EQ(fingerprint(MeshIndex(mesh)), fingerprint(mesh));
  const auto header = parse_index_header(format_index(MeshIndex(mesh)));
  ASSERT_TRUE(header.ok());
  EXPECT_EQ(header->source, fingerprint(mesh));
  Mesh moved = mesh;
  moved.vertices[0].x = std::nextafter(moved.vertices[0].x, 10.0);
  EXPECT_NE(fingerprint(moved), fingerprint(mesh));
}

TEST(MeshIndexFile, EveryTruncationAndEveryFlippedByteIsAClearError) {
  const auto bytes = format_index(MeshIndex(test::octahedron(1.0)));
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const auto loaded = parse_mesh_index(std::span<const std::byte>(bytes).first(n));
    ASSERT_FALSE(loaded.ok()) << n;
    EXPECT_EQ(loaded.error().kind, ErrorKind::parse);
  }
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    auto damaged = bytes;
    damaged[i] ^= std::byte{0x10};
    const auto loaded = parse_mesh_index(damaged);
    ASSERT_FALSE(loaded.ok()) << i;
    EXPECT_NE(loaded.error().message.find("contain index"), std::string::npos)
        << loaded.error().message;
  }
}

TEST(MeshIndexFile, ForeignAndOtherKindAndOtherVersionFilesAreRefusedByName) {
  const std::string text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto foreign =
      parse_mesh_index(std::as_bytes(std::span<const char>(text.data(), text.size())));
  ASSERT_FALSE(foreign.ok());
  EXPECT_NE(foreign.error().message.find("magic"), std::string::npos);

  const std::vector<MultiPolygon> regions{MultiPolygon{{Polygon{{{{0, 0}, {1, 0}, {0, 1}}}}}}};
  const auto layer = format_index(RegionLayer(regions), fingerprint(regions, Fill::even_odd), {});
  const auto wrong_kind = parse_mesh_index(layer);
  ASSERT_FALSE(wrong_kind.ok());
  EXPECT_NE(wrong_kind.error().message.find("region_layer"), std::string::npos);

  auto later = format_index(MeshIndex(test::octahedron(1.0)));
  const std::uint32_t version = index_format_version + 1;
  std::memcpy(later.data() + 8, &version, 4);
  reseal(later);
  const auto refused = parse_mesh_index(later);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("version"), std::string::npos);
}

// A crafted payload (checksums made right) never reads out of bounds: it is refused, or it
// loads an index whose every array access is in range (the sanitizer builds check this).
TEST(MeshIndexFile, CraftedPayloadsAreRefusedOrAnswerWithoutReadingOutOfBounds) {
  const Mesh mesh = test::octahedron(1.0);
  const auto bytes = format_index(MeshIndex(mesh, {.min_cells = 8}));
  std::vector<Vec3> points = probes(mesh, 50, 9);
  points.resize(60);  // the random ones and the vertices
  std::size_t refused = 0, loaded_count = 0;
  for (std::size_t i = index_header_size; i < bytes.size(); ++i) {
    auto crafted = bytes;
    crafted[i] ^= std::byte{0xff};
    reseal(crafted);
    const auto loaded = parse_mesh_index(crafted);
    if (!loaded.ok()) {
      ++refused;
      continue;
    }
    ++loaded_count;  // e.g. a changed report count or a cell's answer: loads, and stays in bounds
    std::vector<Location> out(points.size());
    loaded->locate(points, out, {.threads = 1});
  }
  EXPECT_GT(refused, 0u);
  EXPECT_GT(loaded_count, 0u);
}

// The image that `contain index build` writes piece by piece (some pieces the index's own
// arrays) is the formatted file, for every kind of mesh index: grid, few queries (no grid),
// winding number; and checksums over pieces of any split are the checksum of the whole.
TEST(MeshIndexFile, ImagePiecesJoinedAreTheFormattedFileAndChecksumsStreamAcrossPieces) {
  Mesh open = test::grid_cube(0, 1, 2);
  open.triangles.pop_back();
  const Mesh torus = scenes::torus(1.0, 0.4, 24, 12);
  for (const MeshIndex& index :
       {MeshIndex(torus), MeshIndex(torus, {.queries = 1}), MeshIndex(open), MeshIndex(Mesh{})}) {
    const std::vector<std::byte> bytes = format_index(index);
    const IndexImage image = index_image(index);
    EXPECT_EQ(image.size(), bytes.size());
    std::vector<std::byte> joined;
    for (const std::span<const std::byte> piece : image.pieces())
      joined.insert(joined.end(), piece.begin(), piece.end());
    EXPECT_EQ(joined, bytes);
    ASSERT_TRUE(parse_mesh_index(bytes).ok());
  }
  EXPECT_GT(index_image(MeshIndex(torus)).pieces().size(), 1u);  // arrays by reference
}

// The records' padding is written as zeros even where a crafted file held other bytes there:
// a loaded index saves the bytes of the fresh one.
TEST(MeshIndexFile, LoadedIndexSavesTheFreshBytesWhateverItsFileHeldInThePadding) {
  const MeshIndex fresh(test::octahedron(1.0));
  const std::vector<std::byte> bytes = format_index(fresh);
  // The first record: after the regime, the parity flag, the report (10 counts, no pinch
  // vertices: a count, the Euler characteristic, the genus flag and value, the volume) and the
  // records' count; its padding 97 bytes in.
  const std::size_t first_record = index_header_size + 2 + 10 * 8 + 8 + 8 + 1 + 8 + 8 + 8;
  const std::size_t padding = first_record + 97;
  ASSERT_EQ(bytes[padding], std::byte{0});
  auto crafted = bytes;
  for (std::size_t i = padding; i < padding + 7; ++i)
    crafted[i] = std::byte{0xA5};
  reseal(crafted);
  const auto loaded = parse_mesh_index(crafted);
  ASSERT_TRUE(loaded.ok()) << loaded.error().what();
  EXPECT_EQ(format_index(*loaded), bytes);
}

// The file of an index built for saving only (MeshIndexToSave: the lists as triangle numbers,
// no references with boxes) against the file of the index that answers, built from the same
// mesh and options: byte for byte, with the same regime, report and sizes.
void expect_saved_as_in_memory(const Mesh& mesh, const MeshIndexOptions& options = {}) {
  const MeshIndex fresh(mesh, options);
  const MeshIndexToSave to_save(mesh, options);
  EXPECT_EQ(to_save.regime(), fresh.regime());
  EXPECT_EQ(to_save.report().closed(), fresh.report().closed());
  EXPECT_EQ(to_save.stats().cells, fresh.stats().cells);
  EXPECT_EQ(to_save.stats().surface_cells, fresh.stats().surface_cells);
  EXPECT_EQ(to_save.stats().cell_refs, fresh.stats().cell_refs);
  const IndexImage image = to_save.image();
  std::vector<std::byte> joined;
  for (const std::span<const std::byte> piece : image.pieces())
    joined.insert(joined.end(), piece.begin(), piece.end());
  EXPECT_EQ(image.size(), joined.size());
  EXPECT_TRUE(joined == format_index(fresh)) << mesh.triangles.size() << " triangles";
}

// The records' float boxes are the tightest around their corners, bit for bit (a zero's sign
// too): lo the largest float <= the least corner coordinate, hi the least float >= the greatest,
// for coordinates on floats and between them, zeros of both signs, tiny and subnormal doubles and
// doubles beyond the float range, in the grid's records and in those of an index for few queries.
TEST(MeshIndexFile, RecordBoxesAreTheTightestFloatsAroundTheCorners) {
  const double values[] = {0.0,     -0.0,       1e-300,      -1e-300,   1e-45,
                           -1e-45,  0.1,        -0.1,        1.0,       -3.0,
                           1.0 / 3, 16777217.0, -16777217.0, 1.0000001, 3.4028234663852886e38,
                           3.5e38,  -3.5e38,    1e300,       -1e300,    0x1p-149};
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<std::size_t> pick(0, std::size(values) - 1);
  Mesh mesh;
  for (int t = 0; t < 60; ++t) {
    const auto first = static_cast<std::int32_t>(mesh.vertices.size());
    for (int v = 0; v < 4; ++v)
      mesh.vertices.push_back({values[pick(rng)], values[pick(rng)], values[pick(rng)]});
    // A tetrahedron's four faces: closed whatever its corners.
    mesh.triangles.push_back({first, first + 2, first + 1});
    mesh.triangles.push_back({first, first + 1, first + 3});
    mesh.triangles.push_back({first + 1, first + 2, first + 3});
    mesh.triangles.push_back({first + 2, first, first + 3});
  }
  auto below = [](double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  };
  auto above = [](double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  };
  for (const std::size_t queries : {std::size_t{0}, std::size_t{1}}) {
    const std::vector<std::byte> bytes = format_index(MeshIndex(mesh, {.queries = queries}));
    // After the regime, the parity flag, the report (10 counts, the pinch vertices, the Euler
    // characteristic, the genus flag and value, the volume): the records' count, the records.
    std::size_t at = index_header_size + 2 + 10 * 8;
    std::uint64_t n = 0;
    std::memcpy(&n, bytes.data() + at, 8);
    at += 8 + 4 * n + 8 + 1 + 8 + 8;
    std::memcpy(&n, bytes.data() + at, 8);
    at += 8;
    ASSERT_EQ(n, mesh.triangles.size());
    for (std::size_t r = 0; r < n; ++r, at += 104) {
      double corner[9];
      float lo[3], hi[3];
      std::memcpy(corner, bytes.data() + at, sizeof corner);
      std::memcpy(lo, bytes.data() + at + 72, sizeof lo);
      std::memcpy(hi, bytes.data() + at + 84, sizeof hi);
      for (int d = 0; d < 3; ++d) {
        const float want_lo = below(std::min({corner[d], corner[3 + d], corner[6 + d]}));
        const float want_hi = above(std::max({corner[d], corner[3 + d], corner[6 + d]}));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(lo[d]), std::bit_cast<std::uint32_t>(want_lo))
            << r << " " << d << " " << corner[d] << " " << corner[3 + d] << " " << corner[6 + d];
        ASSERT_EQ(std::bit_cast<std::uint32_t>(hi[d]), std::bit_cast<std::uint32_t>(want_hi))
            << r << " " << d << " " << corner[d] << " " << corner[3 + d] << " " << corner[6 + d];
      }
    }
  }
}

// A torus's connectivity (closed) with its vertices moved at random: self-intersecting,
// overlapping, folded, some of it inverted.
Mesh jittered_torus(std::mt19937_64& rng, double jitter) {
  Mesh mesh = scenes::torus(1.0, 0.4, 20, 10);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (Vec3& v : mesh.vertices)
    v = v + Vec3{u(rng), u(rng), u(rng)};
  return mesh;
}

TEST(MeshIndexToSave, WritesTheBytesOfTheInMemoryIndexOnRandomMeshesAndGrids) {
  std::mt19937_64 rng(4242);
  for (int round = 0; round < 6; ++round) {
    const Mesh mesh = jittered_torus(rng, round < 3 ? 0.02 : 0.5);
    expect_saved_as_in_memory(mesh);
    // Coarse grids (many triangles a cell, big triangles over many cells) and fine ones.
    expect_saved_as_in_memory(mesh, {.cells_per_triangle = 0.5, .min_cells = 8});
    expect_saved_as_in_memory(mesh, {.cells_per_triangle = 200.0});
    expect_saved_as_in_memory(mesh, {.max_cells = 64});
  }
  // Integer corners: triangles on grid planes, shared planes, coincident vertices.
  for (int round = 0; round < 4; ++round) {
    Mesh mesh = scenes::torus(1.0, 0.4, 12, 6);
    std::uniform_int_distribution<int> u(0, 4);
    for (Vec3& v : mesh.vertices)
      v = Vec3{double(u(rng)), double(u(rng)), double(u(rng))};
    expect_saved_as_in_memory(mesh);
    expect_saved_as_in_memory(mesh, {.min_cells = 27});
  }
  expect_saved_as_in_memory(scenes::torus(1.0, 0.4, 48, 24));
}

TEST(MeshIndexToSave, WritesTheBytesOfTheInMemoryIndexOnDegenerateMeshes) {
  // A flat closed mesh (a square and its reverse: a grid one cell thick), a tetrahedron of
  // coplanar corners (zero volume), a collapsed one (every corner on a line), a cube with a
  // duplicated pair of triangles, a cube with one triangle flipped (ray parity), and overlapping
  // cubes (winding number 2).
  const Mesh flat{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                  {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}}};
  const Mesh coplanar{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}},
                      {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
  const Mesh collinear{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}},
                       {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
  Mesh duplicated = test::grid_cube(0, 1, 2);
  duplicated.triangles.push_back(duplicated.triangles[0]);
  duplicated.triangles.push_back(
      {duplicated.triangles[0][0], duplicated.triangles[0][2], duplicated.triangles[0][1]});
  Mesh flipped = test::grid_cube(0, 2, 2);
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  Mesh overlap = test::grid_cube(0, 2, 1);
  const Mesh other = test::grid_cube(1, 3, 1);
  const auto shift = static_cast<std::int32_t>(overlap.vertices.size());
  overlap.vertices.insert(overlap.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (TriangleIndices t : other.triangles)
    overlap.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  for (const Mesh& mesh : {flat, coplanar, collinear, duplicated, flipped, overlap,
                           test::octahedron(1.0), test::l_prism()}) {
    expect_saved_as_in_memory(mesh);
    expect_saved_as_in_memory(mesh, {.min_cells = 1});
  }
}

TEST(MeshIndexToSave, WritesTheBytesOfTheInMemoryIndexWithoutAGrid) {
  // Empty, vertices without triangles, an open mesh (winding number), and the exact regime for
  // few queries (the mesh kept, no grid).
  Mesh open = test::grid_cube(0, 1, 2);
  open.triangles.pop_back();
  const Mesh lone_vertices{{{0, 0, 0}, {1, 2, 3}}, {}};
  for (const Mesh& mesh : {Mesh{}, lone_vertices, open}) {
    expect_saved_as_in_memory(mesh);
  }
  expect_saved_as_in_memory(open, {.winding_accuracy = 2.0});
  expect_saved_as_in_memory(scenes::torus(1.0, 0.4, 24, 12), {.queries = 1});
  EXPECT_EQ(MeshIndexToSave(open).regime(), MeshRegime::winding_number);
}

// Built for saving, the records' hashes are summed as the records are made (in cell order, or
// in mesh order for the winding regime): the header's fingerprint is still the mesh's.
TEST(MeshIndexToSave, HeaderFingerprintIsTheMeshsFingerprintInEveryRegime) {
  std::mt19937_64 rng(77);
  Mesh open = test::grid_cube(0, 1, 2);
  open.triangles.pop_back();
  const Mesh torus = jittered_torus(rng, 0.3);
  struct Case {
    const Mesh* mesh;
    MeshIndexOptions options;
  };
  for (const Case& c :
       {Case{&torus, {}}, Case{&torus, {.cells_per_triangle = 0.5}}, Case{&torus, {.queries = 1}},
        Case{&open, {}}, Case{&open, {.min_cells = 1}}}) {
    const std::vector<std::byte> bytes = MeshIndexToSave(*c.mesh, c.options).image().join();
    const auto header = parse_index_header(bytes);
    ASSERT_TRUE(header);
    EXPECT_EQ(header->source, fingerprint(*c.mesh));
  }
}

std::vector<MultiPolygon> random_layer(std::mt19937_64& rng, int count) {
  std::vector<MultiPolygon> regions;
  for (int r = 0; r < count; ++r) {
    MultiPolygon region;
    region.polygons.push_back(Polygon{test::random_integer_rings(rng, 2, 9, 12)});
    regions.push_back(std::move(region));
  }
  regions.push_back(MultiPolygon{});  // an empty region holds no point
  return regions;
}

TEST(RegionLayerFile, LoadedLayersAnswerExactlyAsFreshUnderEveryFill) {
  std::mt19937_64 rng(11);
  const std::vector<MultiPolygon> regions = random_layer(rng, 40);
  std::vector<Vec2> points;
  std::uniform_real_distribution<double> coordinate(-1.0, 13.0);
  for (int i = 0; i < 2000; ++i)
    points.push_back({coordinate(rng), coordinate(rng)});
  for (int x = -1; x <= 13; ++x)  // integer points: the vertices, on edges, on grid lines
    for (int y = -1; y <= 13; ++y)
      points.push_back({static_cast<double>(x), static_cast<double>(y)});
  const std::vector<std::string> ids{regions.size(), "id"};
  for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
    const RegionLayer fresh(regions, {.fill = fill});
    auto loaded = parse_region_layer(format_index(fresh, fingerprint(regions, fill), ids));
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    EXPECT_EQ(loaded->ids, ids);
    EXPECT_EQ(loaded->source, fingerprint(regions, fill));
    EXPECT_EQ(loaded->layer.fill(), fill);
    EXPECT_EQ(loaded->layer.stats().edge_refs, fresh.stats().edge_refs);
    const HolderTable a = fresh.locate(points, {.threads = 1});
    const HolderTable b = loaded->layer.locate(points, {.threads = 1});
    EXPECT_EQ(a, b);
  }
  EXPECT_NE(fingerprint(regions, Fill::even_odd), fingerprint(regions, Fill::nonzero));
}

TEST(RegionLayerFile, TruncatedFlippedAndCraftedFilesAreRefusedOrSafe) {
  std::mt19937_64 rng(12);
  const std::vector<MultiPolygon> regions = random_layer(rng, 3);
  const auto bytes = format_index(RegionLayer(regions), 1, {});
  for (std::size_t n = 0; n < bytes.size(); n += 3)
    ASSERT_FALSE(parse_region_layer(std::span<const std::byte>(bytes).first(n)).ok()) << n;
  const std::vector<Vec2> points{{0, 0}, {1, 1}, {5, 5}, {2.5, 7}, {12, 12}, {6, 3}};
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    auto damaged = bytes;
    damaged[i] ^= std::byte{0x04};
    ASSERT_FALSE(parse_region_layer(damaged).ok()) << i;
    if (i < index_header_size) continue;
    reseal(damaged);
    const auto loaded = parse_region_layer(damaged);
    if (loaded.ok()) (void)loaded->layer.locate(points, {.threads = 1});
  }
}

TEST(PolygonIndexFile, LoadedPolygonIndexAnswersExactlyAsFreshAndFlippedBytesAreRefused) {
  std::mt19937_64 rng(13);
  for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
    const std::vector<Ring> rings = test::random_integer_rings(rng, 3, 12, 10);
    const PolygonIndex fresh(rings, {.fill = fill});
    const std::vector<MultiPolygon> region{MultiPolygon{{Polygon{rings}}}};
    const auto bytes = format_index(fresh, fingerprint(region, fill));
    auto loaded = parse_polygon_index(bytes);
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    EXPECT_EQ(loaded->fill(), fill);
    EXPECT_EQ(parse_index_header(bytes)->source, fingerprint(region, fill));
    std::vector<Vec2> points = scenes::uniform_points(Box2{{-1, -1}, {11, 11}}, 3000, 14);
    for (int x = -1; x <= 11; ++x)  // the vertices, points on edges and on grid lines
      for (int y = -1; y <= 11; ++y)
        points.push_back({static_cast<double>(x), static_cast<double>(y)});
    std::vector<Location> a(points.size()), b(points.size());
    fresh.locate(points, a, {.threads = 1});
    loaded->locate(points, b, {.threads = 1});
    EXPECT_EQ(a, b);
    for (std::size_t i = 0; i < bytes.size(); i += 23) {
      auto damaged = bytes;
      damaged[i] ^= std::byte{0x40};
      ASSERT_FALSE(parse_polygon_index(damaged).ok()) << i;
    }
    EXPECT_FALSE(parse_region_layer(bytes).ok());  // another kind
  }
}

// Where a saved PolygonIndex's arrays lie in its file (the order RegionLayerFile writes them:
// fill, box, two axes, then each array after its count): offsets of their first elements.
struct PolygonIndexLayout {
  std::size_t cells = 0, cell_count = 0;            // std::uint32_t codes
  std::size_t edge_cells = 0, edge_cell_count = 0;  // 5 four-byte fields each
  std::size_t side_edges = 0, side_edge_count = 0;  // l, r, dir: 36 bytes each
};

template <class T>
T read_at(std::span<const std::byte> bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

template <class T>
void write_at(std::vector<std::byte>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

PolygonIndexLayout layout_of(std::span<const std::byte> bytes) {
  PolygonIndexLayout l;
  std::size_t at = index_header_size + 1 + 32 + 20 + 20;
  const auto array = [&](std::size_t element, std::size_t& count) {
    count = static_cast<std::size_t>(read_at<std::uint64_t>(bytes, at));
    const std::size_t first = at + 8;
    at = first + element * count;
    return first;
  };
  std::size_t edge_count = 0;
  l.cells = array(4, l.cell_count);
  l.edge_cells = array(20, l.edge_cell_count);
  array(32, edge_count);
  l.side_edges = array(36, l.side_edge_count);
  return l;
}

// locate finds an edge cell's record by its code, locate_settled by its rank among the edge
// cells: codes that are not 2, 3, 4, ... in cell order (each below the edge cells' count + 2,
// which is all the loader checked before) are refused, not read past the records.
TEST(PolygonIndexFile, CellCodesThatDoNotCountTheEdgeCellsInCellOrderAreRefused) {
  std::mt19937_64 rng(15);
  const std::vector<Ring> rings{test::random_star(rng, 40, 0.0, 0.0, 1.0)};
  const PolygonIndex index(std::span<const Ring>(rings), {.min_cells = 256});
  const auto bytes = format_index(index, 0);
  const PolygonIndexLayout l = layout_of(bytes);
  ASSERT_EQ(l.cell_count, index.stats().cells);
  ASSERT_EQ(l.edge_cell_count, index.stats().edge_cells);
  std::vector<std::size_t> edge, empty;  // where the codes of edge cells and of empty cells lie
  for (std::size_t c = 0; c < l.cell_count; ++c) {
    const std::size_t at = l.cells + 4 * c;
    (read_at<std::uint32_t>(bytes, at) >= 2 ? edge : empty).push_back(at);
  }
  ASSERT_GE(edge.size(), 3U);
  ASSERT_FALSE(empty.empty());
  const auto last = static_cast<std::uint32_t>(edge.size() + 1);
  using Change = std::vector<std::pair<std::size_t, std::uint32_t>>;  // (where, new code)
  const std::vector<Change> changes{
      {{edge[1], 2}},                // a code repeated
      {{edge[1], 2}, {edge[2], 2}},  // three cells coded 2
      {{edge[0], 3}, {edge[1], 2}},  // two codes swapped
      {{empty.front(), last}},       // an empty cell given the last record too
      {{edge.back(), 0}},            // an edge cell made empty: a record left over
      {{edge.back(), last - 1}},     // ... or read twice
  };
  auto resealed = bytes;
  reseal(resealed);
  ASSERT_TRUE(parse_polygon_index(resealed).ok());
  for (std::size_t k = 0; k < changes.size(); ++k) {
    auto crafted = bytes;
    for (const auto& [at, code] : changes[k])
      write_at(crafted, at, code);
    reseal(crafted);
    const auto loaded = parse_polygon_index(crafted);
    ASSERT_FALSE(loaded.ok()) << k;
    EXPECT_NE(loaded.error().message.find("cell code"), std::string::npos)
        << k << ": " << loaded.error().message;
  }
}

// locate_settled takes the side edge of a cell of one edge to be that edge (the builder's side
// edges are the cell's edges that cross its right side): a file where it is not is refused.
TEST(PolygonIndexFile, OneEdgeCellWhoseSideEdgesAreNotItsEdgeIsRefused) {
  std::mt19937_64 rng(16);
  const std::vector<Ring> rings{test::random_star(rng, 40, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  const auto bytes = format_index(index, 0);
  const PolygonIndexLayout l = layout_of(bytes);
  ASSERT_EQ(l.edge_cell_count, index.stats().edge_cells);
  // The record of a cell of one edge that crosses its right side.
  std::size_t record = 0;
  for (std::size_t k = 0; k < l.edge_cell_count && record == 0; ++k) {
    const std::size_t at = l.edge_cells + 20 * k;
    const auto field = [&](int f) { return read_at<std::uint32_t>(bytes, at + 4 * f); };
    if (field(1) - field(0) != 1 || field(3) - field(2) != 1 || field(3) >= l.side_edge_count)
      continue;
    // The next side edge is another edge (not the same one crossing a cell further right).
    const std::byte* side = bytes.data() + l.side_edges + 36 * field(2);
    if (std::memcmp(side, side + 36, 36) != 0) record = at;
  }
  ASSERT_NE(record, 0U);
  const auto side_begin = read_at<std::uint32_t>(bytes, record + 8);
  const std::size_t dir = l.side_edges + 36 * side_begin + 32;
  std::vector<std::vector<std::byte>> crafted(3, bytes);
  write_at(crafted[0], dir, -read_at<std::int32_t>(bytes, dir));  // its direction reversed
  write_at(crafted[1], record + 12, side_begin + 2);              // a second side edge
  write_at(crafted[2], record + 8, side_begin + 1);               // another cell's side edge
  write_at(crafted[2], record + 12, side_begin + 2);
  for (std::size_t k = 0; k < crafted.size(); ++k) {
    reseal(crafted[k]);
    const auto loaded = parse_polygon_index(crafted[k]);
    ASSERT_FALSE(loaded.ok()) << k;
    EXPECT_NE(loaded.error().message.find("one-edge cell"), std::string::npos)
        << k << ": " << loaded.error().message;
  }
}

TEST(RegionLayerFile, RegionWithoutAGridWhoseBoxHoldsPointsIsRefused) {
  // One empty region: payload = fill (1 byte), region count (8), the region's fill (1), its box.
  auto bytes = format_index(RegionLayer(std::vector<MultiPolygon>{MultiPolygon{}}), 0, {});
  ASSERT_TRUE(parse_region_layer(bytes).ok());
  const double box[4] = {0.0, 0.0, 1.0, 1.0};  // min.x, min.y, max.x, max.y
  std::memcpy(bytes.data() + index_header_size + 10, box, sizeof box);
  reseal(bytes);
  const auto loaded = parse_region_layer(bytes);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().message.find("without a grid"), std::string::npos);
}

}  // namespace
}  // namespace contain::inside
