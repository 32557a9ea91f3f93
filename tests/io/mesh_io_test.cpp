#include "contain/io/mesh_io.h"

#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <fstream>
#include <random>

#include "io/temp_file.h"
#include "support/shared_corpus.h"

namespace contain::io {
namespace {

// A closed mesh with awkward coordinates: random doubles (not floats), a signed zero, a
// subnormal, extreme exponents.
Mesh awkward_mesh() {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  for (int i = 0; i < 40; ++i)
    m.vertices.push_back({u(rng) / 3.0, u(rng) * 1e-200, u(rng) * 1e250});
  m.vertices[0] = {-0.0, std::numeric_limits<double>::denorm_min(), 0.1};
  for (int i = 0; i + 2 < 40; ++i)
    m.triangles.push_back({i, i + 1, i + 2});
  return m;
}

bool bitwise_equal(const Mesh& a, const Mesh& b) {
  if (a.triangles != b.triangles || a.vertices.size() != b.vertices.size()) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    for (auto [x, y] :
         {std::pair{a.vertices[i].x, b.vertices[i].x}, std::pair{a.vertices[i].y, b.vertices[i].y},
          std::pair{a.vertices[i].z, b.vertices[i].z}}) {
      if (std::bit_cast<std::uint64_t>(x) != std::bit_cast<std::uint64_t>(y)) return false;
    }
  }
  return true;
}

// Strings the library returns are the enumerators' names (the naming rule 7); the readers'
// messages keep the words for a person.
TEST(MeshIo, FormatNamesAreTheEnumeratorsAndMessagesWordThemForAPerson) {
  EXPECT_STREQ(to_string(MeshFormat::obj), "obj");
  EXPECT_STREQ(to_string(MeshFormat::stl_ascii), "stl_ascii");
  EXPECT_STREQ(to_string(MeshFormat::ply_binary_little_endian), "ply_binary_little_endian");
  EXPECT_STREQ(to_string(MeshFormat::ply_binary_big_endian), "ply_binary_big_endian");
  const auto empty = parse_mesh("solid x\nendsolid x\n", MeshFormat::stl_ascii, "e.stl");
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().message, "ASCII STL file without faces: no mesh");
}

TEST(MeshIo, LosslessFormatsRoundTripBitForBit) {
  const Mesh m = awkward_mesh();
  for (MeshFormat f : {MeshFormat::obj, MeshFormat::off, MeshFormat::ply_ascii,
                       MeshFormat::ply_binary_little_endian, MeshFormat::ply_binary_big_endian,
                       MeshFormat::stl_ascii}) {
    auto back = parse_mesh(format_mesh(m, f), f, "rt");
    ASSERT_TRUE(back.ok()) << to_string(f) << ": " << back.error().what();
    EXPECT_EQ(back->info.format, f);
    EXPECT_EQ(back->info.faces, static_cast<std::int64_t>(m.triangles.size()));
    // STL welds -0 with +0 and cannot keep a vertex's identity apart from its position, but
    // this mesh has no duplicate positions, and corners come back in first-seen order.
    EXPECT_TRUE(bitwise_equal(back->mesh, m)) << to_string(f);
  }
}

// ASCII PLY's body is OFF's line for line (the same writer): only the headers differ.
TEST(MeshIo, AsciiPlyBodyIsTheOffBodyUnderItsOwnHeader) {
  const Mesh m = awkward_mesh();
  const std::string off = format_mesh(m, MeshFormat::off);
  const std::string ply = format_mesh(m, MeshFormat::ply_ascii);
  const std::string off_header = "OFF\n40 38 0\n";
  const std::string ply_end = "end_header\n";
  ASSERT_EQ(off.substr(0, off_header.size()), off_header);
  const std::size_t body = ply.find(ply_end);
  ASSERT_NE(body, std::string::npos);
  EXPECT_EQ(ply.substr(body + ply_end.size()), off.substr(off_header.size()));
  EXPECT_NE(ply.find("3 0 1 2\n"), std::string::npos);
}

TEST(MeshIo, BinaryStlRoundTripsMeshesOfFloats) {
  Mesh m = awkward_mesh();
  for (Vec3& v : m.vertices) {
    v = {static_cast<float>(v.x), static_cast<float>(v.y * 1e180), static_cast<float>(v.z / 1e220)};
  }
  m.vertices[0] = {0.5, 0.25, -0.125};
  auto back = parse_mesh(format_mesh(m, MeshFormat::stl_binary), MeshFormat::stl_binary, "rt");
  ASSERT_TRUE(back.ok()) << back.error().what();
  EXPECT_TRUE(bitwise_equal(back->mesh, m));
}

TEST(MeshIo, DispatchesByExtensionCaseInsensitivelyAndWritesByExtension) {
  Mesh m = awkward_mesh();
  for (Vec3& v : m.vertices)
    v.z = v.z * 1e-250;  // within float range, for STL
  for (const char* ext : {".obj", ".OFF", ".Ply", ".stl"}) {
    test::TempFile file(ext);
    ASSERT_TRUE(write_mesh(m, file.path()).ok()) << ext;
    auto back = read_mesh(file.path());
    ASSERT_TRUE(back.ok()) << ext << ": " << back.error().what();
    EXPECT_EQ(back->mesh.triangles, m.triangles) << ext;
  }
  EXPECT_EQ(mesh_format_for_path("a/b.STL"), MeshFormat::stl_binary);
  EXPECT_EQ(mesh_format_for_path("a/b.ply"), MeshFormat::ply_binary_little_endian);
  EXPECT_FALSE(mesh_format_for_path("a/b.txt").has_value());
}

TEST(MeshIo, WritesTheRequestedFormatWhateverTheExtension) {
  const Mesh m = awkward_mesh();
  test::TempFile file(".ply");
  ASSERT_TRUE(write_mesh(m, file.path(), {.format = MeshFormat::ply_ascii}).ok());
  auto back = read_mesh(file.path());
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->info.format, MeshFormat::ply_ascii);
}

TEST(MeshIo, ReportsMissingFilesUnknownExtensionsAndUnwritablePaths) {
  auto missing = read_mesh("/nonexistent/m.obj");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
  EXPECT_EQ(missing.error().source, "/nonexistent/m.obj");
  test::TempFile txt(".txt", "v 0 0 0\n");
  auto unknown = read_mesh(txt.path());
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().kind, ErrorKind::unsupported);
  auto dir = read_mesh(std::filesystem::temp_directory_path() / ".");
  EXPECT_FALSE(dir.ok());
  auto unwritable = write_mesh(awkward_mesh(), "/nonexistent/dir/m.off");
  ASSERT_FALSE(unwritable.ok());
  EXPECT_EQ(unwritable.error().kind, ErrorKind::io);
  test::TempFile stl(".stl");
  auto too_large = write_mesh(awkward_mesh(), stl.path());
  ASSERT_FALSE(too_large.ok());
  EXPECT_EQ(too_large.error().kind, ErrorKind::invalid_value);
  auto no_format = write_mesh(awkward_mesh(), "/tmp/m.xyz");
  ASSERT_FALSE(no_format.ok());
  EXPECT_EQ(no_format.error().kind, ErrorKind::unsupported);
}

// Every truncation and many random corruptions of each format give an answer (a mesh or an
// Error), never a crash, a hang or a sanitizer report; a truncated binary file is an error.
TEST(MeshIo, SurvivesEveryTruncationAndRandomCorruption) {
  Mesh m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
         {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  std::mt19937_64 rng(23);
  for (MeshFormat f : {MeshFormat::obj, MeshFormat::off, MeshFormat::stl_ascii,
                       MeshFormat::stl_binary, MeshFormat::ply_ascii,
                       MeshFormat::ply_binary_little_endian, MeshFormat::ply_binary_big_endian}) {
    const std::string bytes = format_mesh(m, f);
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      auto r = parse_mesh(std::string_view(bytes).substr(0, n), f, "cut");
      const bool binary = f == MeshFormat::stl_binary ||
                          f == MeshFormat::ply_binary_little_endian ||
                          f == MeshFormat::ply_binary_big_endian;
      if (binary) {
        EXPECT_FALSE(r.ok()) << to_string(f) << " cut at " << n;
      }
    }
    for (int trial = 0; trial < 300; ++trial) {
      std::string copy = bytes;
      for (int k = 0; k < 3; ++k)
        copy[rng() % copy.size()] = static_cast<char>(rng() & 0xFF);
      auto r = parse_mesh(copy, f, "corrupt");
      if (r.ok()) {
        EXPECT_TRUE(Mesh::from_arrays(r->mesh.vertices, r->mesh.triangles).ok());
      }
    }
  }
}

struct CorpusMesh {
  const char* path;
  std::size_t triangles;
  std::size_t vertices;
};

// The counts of shared/corpus/meshes/README.md.
TEST(MeshIo, ReadsEveryCorpusMeshWithTheCountsOfItsReadme) {
  CONTAIN_REQUIRE_SHARED();
  const auto dir = *test::shared_dir() / "corpus" / "meshes";
  const CorpusMesh table[] = {
      {"spot.obj", 5856, 2930},
      {"fandisk.obj", 12946, 6475},
      {"rocker-arm.obj", 20088, 10044},
      {"fertility.off", 9000, 4494},
      {"armadillo.obj", 86482, 43243},
      {"cow.obj", 5804, 2903},
      {"stanford-bunny.obj", 69451, 35947},
      {"lion.off", 16674, 8356},
  };
  for (const CorpusMesh& c : table) {
    const auto start = std::chrono::steady_clock::now();
    auto r = read_mesh(dir / c.path);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(r.ok()) << c.path << ": " << r.error().what();
    EXPECT_EQ(r->mesh.triangles.size(), c.triangles) << c.path;
    EXPECT_EQ(r->mesh.vertices.size(), c.vertices) << c.path;
    EXPECT_EQ(r->info.faces, static_cast<std::int64_t>(c.triangles)) << c.path;
    const double mb = static_cast<double>(std::filesystem::file_size(dir / c.path)) / 1e6;
    std::cout << "[ mesh ] " << c.path << ": " << mb << " MB in " << seconds << " s, "
              << mb / seconds << " MB/s\n";
  }
}

// The derived and constructed meshes of shared/corpus/mesh-cases: the counts of each header,
// all triangles, and each converts to every other format and back unchanged.
TEST(MeshIo, ReadsEveryMeshCaseAndConvertsItLosslessly) {
  CONTAIN_REQUIRE_SHARED();
  const auto dir = *test::shared_dir() / "corpus" / "mesh-cases" / "meshes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".off") continue;
    ++count;
    std::ifstream in(entry.path());
    std::string magic;
    std::size_t nv = 0;
    std::size_t nf = 0;
    in >> magic >> nv >> nf;
    auto r = read_mesh(entry.path());
    ASSERT_TRUE(r.ok()) << r.error().what();
    EXPECT_EQ(r->mesh.vertices.size(), nv) << entry.path();
    EXPECT_EQ(r->mesh.triangles.size(), nf) << entry.path();
    for (MeshFormat f : {MeshFormat::obj, MeshFormat::ply_binary_little_endian}) {
      auto back = parse_mesh(format_mesh(r->mesh, f), f, "rt");
      ASSERT_TRUE(back.ok());
      EXPECT_TRUE(bitwise_equal(back->mesh, r->mesh)) << entry.path() << " " << to_string(f);
    }
  }
  EXPECT_EQ(count, 16);
}

TEST(MeshIo, AFileWithoutFacesIsRefusedUnlessTheEmptyMeshIsAllowed) {
  // The mesh booleans read it as the empty solid, and write an empty result so.
  for (const auto& [text, family] :
       {std::pair<std::string, MeshFormat>{"OFF\n0 0 0\n", MeshFormat::off},
        {"OFF\n2 0 0\n0 0 0\n1 1 1\n", MeshFormat::off},
        {"v 0 0 0\n", MeshFormat::obj}}) {
    auto refused = parse_mesh(text, family, "e");
    ASSERT_FALSE(refused.ok()) << text;
    EXPECT_EQ(refused.error().kind, ErrorKind::degenerate);
    auto empty = parse_mesh(text, family, "e", {.allow_empty = true});
    ASSERT_TRUE(empty.ok()) << empty.error().what();
    EXPECT_TRUE(empty->mesh.triangles.empty());
  }
  EXPECT_EQ(
      parse_mesh(format_mesh(Mesh{}, MeshFormat::off), MeshFormat::off, "e", {.allow_empty = true})
          ->mesh,
      Mesh{});
  // Allowing no faces allows nothing else: a bad coordinate is still refused.
  auto nan = parse_mesh("OFF\n1 0 0\nnan 0 0\n", MeshFormat::off, "e", {.allow_empty = true});
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_value);
}

}  // namespace
}  // namespace contain::io
