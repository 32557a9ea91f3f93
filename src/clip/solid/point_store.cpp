// The point store of the mesh boolean: every exact point of the arrangement once, found by its
// nearest doubles (PointTable) and then exact equality among the few points sharing them.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::clip::solid {

std::uint64_t PointTable::hash(Vec3 v) {
  // Equal doubles, equal bits (-0 + 0 is +0); the three mixed, then MurmurHash3's finalizer so
  // that every bit reaches the low ones (integer coordinates have zero low mantissa bits).
  const std::uint64_t x = std::bit_cast<std::uint64_t>(v.x + 0.0);
  const std::uint64_t y = std::bit_cast<std::uint64_t>(v.y + 0.0);
  const std::uint64_t z = std::bit_cast<std::uint64_t>(v.z + 0.0);
  std::uint64_t h = x * 0x9e3779b97f4a7c15ULL + y * 0xc2b2ae3d27d4eb4fULL + z;
  h ^= h >> 33U;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33U;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33U;
  return h;
}

void PointTable::reserve(std::size_t points, PointKeys keys) {
  std::size_t size = 16;
  while (size < 2 * points)
    size *= 2;
  if (size <= slots_.size()) return;
  ScratchVector<Slot> old(size);
  old.swap(slots_);
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& s : old) {
    if (s.id < 0) continue;
    std::size_t i = hash(keys[static_cast<std::size_t>(s.id)]) & mask;
    while (slots_[i].id >= 0)
      i = (i + 1) & mask;
    slots_[i] = s;
  }
}

std::size_t PointTable::slot_of(Vec3 v, std::uint64_t h, PointKeys keys) const {
  const std::size_t mask = slots_.size() - 1;
  const auto tag = static_cast<std::uint32_t>(h >> 32U);
  for (std::size_t i = static_cast<std::size_t>(h) & mask;; i = (i + 1) & mask) {
    const Slot& s = slots_[i];
    if (s.id < 0) return i;
    if (s.tag == tag) {
      const Vec3 k = keys[static_cast<std::size_t>(s.id)];
      if (k.x == v.x && k.y == v.y && k.z == v.z) return i;
    }
  }
}

std::pair<std::int32_t, bool> PointTable::try_emplace(Vec3 v, std::int32_t id, PointKeys keys) {
  if (2 * (used_ + 1) > slots_.size()) reserve(2 * (used_ + 1), keys);
  const std::uint64_t h = hash(v);
  Slot& s = slots_[slot_of(v, h, keys)];
  if (s.id >= 0) return {s.id, false};
  s = {id, static_cast<std::uint32_t>(h >> 32U)};
  ++used_;
  return {id, true};
}

std::int32_t PointTable::find(Vec3 v, PointKeys keys) const {
  return slots_.empty() ? -1 : slots_[slot_of(v, hash(v), keys)].id;
}

void PointStore::reserve(std::size_t points) {
  points_.reserve(points);
  // Room for all `points`, though after add_vertices takes a soup's index rounded_ holds only
  // the points after its vertices: the room left over is never touched (no page faults), and
  // reserving only the points after the vertices measured more faults, not fewer (18,871
  // against 18,726 at the union of two 131k-triangle spheres: where the allocator places the
  // smaller block changes which freed pages later allocations reuse).
  rounded_.reserve(points);
  next_.reserve(points);
  first_of_.reserve(points);
  exact_double_.reserve(points);
  // An empty store's table is made by its first point (or taken over from a soup by
  // add_vertices): a table of megabytes zeroed here would be dropped there.
  if (!points_.empty()) first_.reserve(points, keys());
}

std::int32_t PointStore::add(const ExactPoint& p) {
  return add(p, nearest_double(p));
}

std::int32_t PointStore::add(Vec3 v) {
  return add(exact_point(v), v);
}

void PointStore::add_vertices(const Soup& soup) {
  if (!points_.empty() || soup.index.size() != soup.vertices.size()) {
    for (const Vec3 v : soup.vertices)
      (void)add(v);
    return;
  }
  PointTable index = soup.index;
  add_vertices(soup, std::move(index));
}

void PointStore::add_vertices(const Soup& soup, PointTable&& index) {
  if (!points_.empty() || index.size() != soup.vertices.size()) {
    for (const Vec3 v : soup.vertices)
      (void)add(v);
    return;
  }
  // The room reserved before for the crossings stays (a smaller table is rebuilt once; the
  // engine's, sized by make_soup for store_room, is not).
  const std::size_t room = std::max(points_.capacity(), soup.vertices.size());
  // Exchanged, not only moved from: the soup's index is left an empty table (size 0), never a
  // moved-from one whose count would still claim the soup's vertices.
  first_ = std::exchange(index, PointTable{});
  first_.reserve(room, soup.vertices);
  points_.reserve(room);
  for (const Vec3 v : soup.vertices)
    points_.push_back(exact_point(v));
  vertices_ = soup.vertices;  // read there, not copied (add_vertices in engine.h)
  next_.assign(soup.vertices.size(), -1);
  first_of_.reserve(room);
  first_of_.resize(soup.vertices.size());
  for (std::size_t i = 0; i < first_of_.size(); ++i)
    first_of_[i] = static_cast<std::int32_t>(i);
  exact_double_.reserve(room);
  exact_double_.assign(soup.vertices.size(), 1);  // points of doubles
}

std::int32_t PointStore::add(const ExactPoint& p, Vec3 r) {
  const auto id = static_cast<std::int32_t>(points_.size());
  if (id == 0) first_.reserve(std::max<std::size_t>(points_.capacity(), 1), keys());
  const auto [first, fresh] = first_.try_emplace(r, id, keys());
  if (!fresh) {
    std::int32_t i = first;
    for (;; i = next_[static_cast<std::size_t>(i)]) {
      if (same_point(points_[static_cast<std::size_t>(i)], p)) return i;
      if (next_[static_cast<std::size_t>(i)] < 0) break;
    }
    next_[static_cast<std::size_t>(i)] = id;
  }
  points_.push_back(p);
  rounded_.push_back(r);
  next_.push_back(-1);
  first_of_.push_back(first);
  const Enclosure bounds = p.enclosure();
  exact_double_.push_back(bounds.lo == bounds.hi ? 1 : 0);  // (a point of doubles: lo = hi = v)
  return id;
}

std::int32_t PointStore::representative(std::int32_t i) const {
  return first_of_[static_cast<std::size_t>(i)];
}

}  // namespace contain::clip::solid
