// A MeshIndex as bytes (contain/inside/index_file.h): every member of MeshIndex is written and
// read here, in `MeshIndexFile::write` and `MeshIndexFile::read`, and nowhere else, so a change
// of the index's members changes these two functions (and index_format_version).
//
// What is stored and what is checked or recomputed: the triangles are stored whole (corners,
// float box, ray sign, in the index's order) and checked against their corners (the sign
// recomputed exactly, the box holding the corners: any such box is a correct rejection test); a
// cell's triangle list stores triangle numbers and its boxes are copied from the triangles; every
// stored number that indexes an array is checked against it. The winding regime's tree is
// rebuilt from the triangles (the file saves the mesh's validation, not that build).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <utility>

#include "contain/inside/index_file.h"
#include "contain/predicates/perturbed_ray.h"
#include "inside/index_bytes.h"

namespace contain::inside {

struct MeshIndexFile {
  static void write(const MeshIndex& index, index_bytes::Writer& w);
  static Result<MeshIndex> read(index_bytes::Reader& r);
  static Status check_triangles(MeshIndex& index);
  static Mesh soup(const MeshIndex& index);
  static std::vector<MeshIndex::Tri> direct_records(const MeshIndex& index);
  static Result<MeshIndex> read_grid(MeshIndex index, index_bytes::View<std::uint32_t> surface,
                                     index_bytes::View<std::uint32_t> refs);
  static std::uint64_t fingerprint(const MeshIndex& index);
  static MeshIndex build_for_saving(const Mesh& mesh, const MeshIndexOptions& options) {
    return {mesh, options, MeshIndex::ForSaving{}};
  }
};

namespace {

void write_report(const MeshReport& m, index_bytes::Writer& w) {
  for (std::size_t v : {m.vertices, m.referenced_vertices, m.triangles, m.edges, m.border_edges,
                        m.nonmanifold_edges, m.inconsistent_edges, m.degenerate_triangles,
                        m.duplicated_triangles, m.components}) {
    w.put<std::uint64_t>(v);
  }
  w.put_array<std::int32_t>(m.pinch_vertices);
  w.put<std::int64_t>(m.euler_characteristic);
  w.put<std::uint8_t>(m.genus.has_value());
  w.put<std::int64_t>(m.genus.value_or(0));
  w.put(m.signed_volume);
}

Error bad(const char* what) {
  return {ErrorKind::parse, std::string("corrupt index file: ") + what};
}

MeshReport read_report(index_bytes::Reader& r) {
  MeshReport m;
  for (std::size_t* v : {&m.vertices, &m.referenced_vertices, &m.triangles, &m.edges,
                         &m.border_edges, &m.nonmanifold_edges, &m.inconsistent_edges,
                         &m.degenerate_triangles, &m.duplicated_triangles, &m.components}) {
    *v = static_cast<std::size_t>(r.get<std::uint64_t>());
  }
  m.pinch_vertices = r.get_array<std::int32_t>();
  m.euler_characteristic = r.get<std::int64_t>();
  const bool has_genus = r.get<std::uint8_t>() != 0;
  const auto genus = r.get<std::int64_t>();
  if (has_genus) m.genus = genus;
  m.signed_volume = r.get_double();
  return m;
}

}  // namespace

void MeshIndexFile::write(const MeshIndex& index, index_bytes::Writer& w) {
  w.put<std::uint8_t>(static_cast<std::uint8_t>(index.regime_));
  w.put<std::uint8_t>(index.by_parity_ ? 1 : 0);
  write_report(index.report_, w);
  // The records are copied whole: a change of Tri's layout must change index_format_version.
  static_assert(sizeof(MeshIndex::Tri) == 104 && offsetof(MeshIndex::Tri, lo) == 72 &&
                    offsetof(MeshIndex::Tri, s) == 96 && offsetof(MeshIndex::Tri, zero) == 97,
                "MeshIndex::Tri changed: update mesh_index_file.cpp and index_format_version");
  // The records as they lie in memory (their padding is an explicit, zeroed member), by
  // reference: no copy of 10 MB for 100k triangles. An index for few queries keeps the mesh
  // instead: its records are made for the file, member by member into zeroed bytes.
  const bool direct = !index.mesh_.triangles.empty();
  w.reserve((direct ? sizeof(MeshIndex::Tri) * index.mesh_.triangles.size() : 0) + 256);
  if (direct) {
    const std::vector<MeshIndex::Tri> records = direct_records(index);
    std::byte* to = w.put_array_in_place<MeshIndex::Tri>(records.size());
    for (const MeshIndex::Tri& from : records) {
      std::memcpy(to + offsetof(MeshIndex::Tri, a), &from.a, sizeof from.a);
      std::memcpy(to + offsetof(MeshIndex::Tri, b), &from.b, sizeof from.b);
      std::memcpy(to + offsetof(MeshIndex::Tri, c), &from.c, sizeof from.c);
      std::memcpy(to + offsetof(MeshIndex::Tri, lo), from.lo, sizeof from.lo);
      std::memcpy(to + offsetof(MeshIndex::Tri, hi), from.hi, sizeof from.hi);
      std::memcpy(to + offsetof(MeshIndex::Tri, s), &from.s, sizeof from.s);
      to += sizeof(MeshIndex::Tri);
    }
  } else {
    w.put_array_by_reference<MeshIndex::Tri>(index.tris_);
  }
  w.put(index.winding_.accuracy());
  w.put(index.x_);
  w.put(index.y_);
  w.put(index.z_);
  w.put_array_by_reference<std::uint8_t>(index.state_);
  // Every cell's word: a surface cell's number, an empty cell's winding number.
  w.put_array_by_reference<std::uint32_t>(index.surface_);
  w.put_array_by_reference<std::uint32_t>(index.cell_start_);
  // The lists' triangle numbers, as they lie in memory.
  w.put_array_by_reference<std::uint32_t>(index.refs_);
  const MeshIndex::Stats& s = index.stats_;
  for (std::size_t v : {s.triangles, s.cells, s.surface_cells, s.cell_refs})
    w.put<std::uint64_t>(v);
}

Result<MeshIndex> MeshIndexFile::read(index_bytes::Reader& r) {
  MeshIndex index;
  const auto regime = r.get<std::uint8_t>();
  const auto by_parity = r.get<std::uint8_t>();
  index.report_ = read_report(r);
  index.tris_ = r.get_array<MeshIndex::Tri, HugePageAllocator<MeshIndex::Tri>>();
  const double accuracy = r.get_double();
  index.x_ = r.get_axis();
  index.y_ = r.get_axis();
  index.z_ = r.get_axis();
  index.state_ = r.get_array<std::uint8_t, HugePageAllocator<std::uint8_t>>();
  const auto surface = r.get_view<std::uint32_t>();
  index.cell_start_ = r.get_array<std::uint32_t, HugePageAllocator<std::uint32_t>>();
  const auto refs = r.get_view<std::uint32_t>();
  MeshIndex::Stats& s = index.stats_;
  for (std::size_t* v : {&s.triangles, &s.cells, &s.surface_cells, &s.cell_refs})
    *v = static_cast<std::size_t>(r.get<std::uint64_t>());
  if (Status done = r.finish(); !done) return done.error();
  if (regime > 1) return bad("unknown mesh regime");
  if (by_parity > 1) return bad("the parity flag is not 0 or 1");
  index.regime_ = static_cast<MeshRegime>(regime);
  index.by_parity_ = by_parity == 1;
  if (Status t = check_triangles(index); !t) return t.error();
  if (index.regime_ == MeshRegime::winding_number) {
    if (!(accuracy > 0.0) || !std::isfinite(accuracy)) return bad("winding accuracy");
    if (!index.tris_.empty())
      index.winding_ = FastWindingNumber(soup(index), {.accuracy = accuracy});
    if (!index.state_.empty() || !index.cell_start_.empty() || !refs.empty())
      return bad("a winding-number index holds a grid");
    return index;
  }
  return read_grid(std::move(index), surface, refs);
}

// The exact regime's grid, checked: its axes span the triangles' box; every cell's state is 0, 1
// or 2; surface cells numbered below their count; cell_start_ ascending from 0 to the references'
// count; every reference a triangle.
Result<MeshIndex> MeshIndexFile::read_grid(MeshIndex index,
                                           index_bytes::View<std::uint32_t> surface,
                                           index_bytes::View<std::uint32_t> refs) {
  const std::size_t triangles = index.tris_.size();
  index.nx_ = index.x_.cells();
  index.ny_ = index.y_.cells();
  index.nz_ = index.z_.cells();
  const std::size_t cells = static_cast<std::size_t>(index.nx_) *
                            static_cast<std::size_t>(index.ny_) *
                            static_cast<std::size_t>(index.nz_);
  if (triangles == 0 || index.state_.empty()) {
    // An empty mesh, or an index built for few queries (MeshIndexOptions::queries): no grid.
    if (cells != 0 || !index.state_.empty() || !index.cell_start_.empty() || !refs.empty() ||
        !surface.empty()) {
      return bad("an index without a grid holds part of one");
    }
    // Without a grid the index reads a mesh (locate_direct): the triangles', three corners each.
    index.mesh_ = soup(index);
    index.tris_.clear();
    return index;
  }
  const Box3& b = index.bounds_;
  if (cells == 0 || index.state_.size() != cells || index.x_.lines().front() != b.min.x ||
      index.x_.lines().back() != b.max.x || index.y_.lines().front() != b.min.y ||
      index.y_.lines().back() != b.max.y || index.z_.lines().front() != b.min.z ||
      index.z_.lines().back() != b.max.z) {
    return bad("the grid does not match the triangles");
  }
  const HugePageVector<std::uint32_t>& start = index.cell_start_;
  if (start.empty() || start.front() != 0 || start.back() != refs.size() ||
      !std::is_sorted(start.begin(), start.end()) || surface.size() != cells) {
    return bad("the surface cells' lists are malformed");
  }
  index.surface_.assign(cells, 0);
  std::size_t k = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::uint8_t state = index.state_[c];
    if (state > 2) return bad("a cell's state is not 0, 1 or 2");
    index.surface_[c] = surface[c];
    if (state < 2) {
      // An empty cell's state is its winding number's answer.
      if (index.inside_by_count(static_cast<std::int32_t>(surface[c])) != (state == 1))
        return bad("an empty cell's state and winding number disagree");
      continue;
    }
    if (surface[c] != k++) return bad("a surface cell number");
  }
  if (k != start.size() - 1) return bad("the surface cells' count");
  index.refs_.resize(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (refs[i] >= triangles) return bad("a cell lists a triangle that does not exist");
    index.refs_[i] = refs[i];
  }
  index.pack_states();
  index.stats_.nx = index.nx_;
  index.stats_.ny = index.ny_;
  index.stats_.nz = index.nz_;
  return index;
}

// The triangles as the index's own stage (read_triangles) makes them: finite corners, fewer
// than 2^32 (the lists number them in 32 bits), the ray sign exactly the projection's, the float
// box holding the corners (any such box is a correct rejection test). Sets the bounds.
Status MeshIndexFile::check_triangles(MeshIndex& index) {
  if (index.tris_.size() >= (std::size_t{1} << 32)) return bad("too many triangles");
  for (MeshIndex::Tri& t : index.tris_) {
    std::fill(std::begin(t.zero), std::end(t.zero), std::uint8_t{0});  // written back as read
    for (const Vec3& v : {t.a, t.b, t.c}) {
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        return bad("a triangle corner is not finite");
      const double c[3] = {v.x, v.y, v.z};
      for (int d = 0; d < 3; ++d)
        if (!(t.lo[d] <= c[d] && c[d] <= t.hi[d])) return bad("a triangle's box");
      index.bounds_.expand(v);
    }
    if (t.s != predicates::projected_sign(t.a, t.b, t.c)) return bad("a triangle's ray sign");
  }
  index.stats_.triangles = index.tris_.size();
  return Ok{};
}

// The triangles in the index's order, three corners each (the winding number's input).
Mesh MeshIndexFile::soup(const MeshIndex& index) {
  Mesh mesh;
  mesh.vertices.reserve(3 * index.tris_.size());
  mesh.triangles.reserve(index.tris_.size());
  for (const MeshIndex::Tri& t : index.tris_) {
    const auto v = static_cast<std::int32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {t.a, t.b, t.c});
    mesh.triangles.push_back({v, v + 1, v + 2});
  }
  return mesh;
}

// The records of an index for few queries, which keeps the mesh instead (none otherwise).
std::vector<MeshIndex::Tri> MeshIndexFile::direct_records(const MeshIndex& index) {
  std::vector<MeshIndex::Tri> tris;
  tris.reserve(index.mesh_.triangles.size());
  for (const TriangleIndices& t : index.mesh_.triangles) {
    tris.push_back(MeshIndex::make_tri(index.mesh_.vertex(t[0]), index.mesh_.vertex(t[1]),
                                       index.mesh_.vertex(t[2])));
  }
  return tris;
}

std::uint64_t MeshIndexFile::fingerprint(const MeshIndex& index) {
  // Built for saving, the records' hashes were summed as they were made.
  std::uint64_t sum = index.for_saving_ ? index.records_hash_sum_ : 0;
  if (!index.for_saving_) {
    for (const MeshIndex::Tri& t : index.tris_)
      sum += index_bytes::hash_triangle(t.a, t.b, t.c);
  }
  for (const TriangleIndices& t : index.mesh_.triangles) {
    sum += index_bytes::hash_triangle(index.mesh_.vertex(t[0]), index.mesh_.vertex(t[1]),
                                      index.mesh_.vertex(t[2]));
  }
  return index_bytes::finish_fingerprint(sum, index.tris_.size() + index.mesh_.triangles.size());
}

std::uint64_t fingerprint(const MeshIndex& index) {
  return MeshIndexFile::fingerprint(index);
}

IndexImage index_image(const MeshIndex& index) {
  index_bytes::Writer w;
  MeshIndexFile::write(index, w);
  return index_bytes::finish_image(w, IndexKind::mesh_index, fingerprint(index));
}

MeshIndexToSave::MeshIndexToSave(const Mesh& mesh, const MeshIndexOptions& options)
    : index_(MeshIndexFile::build_for_saving(mesh, options)) {}

IndexImage MeshIndexToSave::image() const {
  return index_image(index_);
}

std::vector<std::byte> format_index(const MeshIndex& index) {
  return index_image(index).join();
}

Result<MeshIndex> parse_mesh_index(const IndexHeader& checked) {
  if (checked.kind != IndexKind::mesh_index)
    return index_bytes::wrong_kind(checked.kind, IndexKind::mesh_index);
  index_bytes::Reader r(checked.payload);
  return MeshIndexFile::read(r);
}

Result<MeshIndex> parse_mesh_index(std::span<const std::byte> bytes) {
  auto header = parse_index_header(bytes);
  if (!header) return header.error();
  return parse_mesh_index(*header);
}

}  // namespace contain::inside
