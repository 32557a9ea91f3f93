#pragma once
// The payload of a saved index (contain/inside/index_file.h): a writer that appends numbers and
// arrays, and a reader that checks every count against the bytes left, so that no field of a
// truncated or crafted payload is read past its end. Shared by the per-kind files
// (mesh_index_file.cpp, region_layer_file.cpp).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "contain/core/result.h"
#include "contain/inside/grid_axis.h"
#include "contain/inside/index_file.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::inside::index_bytes {

// Appends after room for the header, which `finish_index` (index_file.cpp) fills in place.
class Writer {
 public:
  Writer() : bytes_(index_header_size) {}

  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::byte*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  // The count, then the elements' bytes. Only for element types without padding: the file must
  // not depend on uninitialized bytes.
  template <class T>
  void put_array(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    const auto* p = reinterpret_cast<const std::byte*>(values.data());
    bytes_.insert(bytes_.end(), p, p + values.size_bytes());
  }
  // The count, then room for n zeroed elements, to be filled in place (no copy of the array
  // made first): their first byte.
  template <class T>
  std::byte* put_array_in_place(std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(n);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n * sizeof(T));  // zeroed: padding bytes never stale
    return bytes_.data() + at;
  }
  // The count, then the elements as they lie in memory, referred to and not copied (IndexImage):
  // they must stay unchanged until the file is written. Only element types whose every byte is
  // set (padding made explicit and zeroed): the file must not depend on uninitialized bytes.
  template <class T>
  void put_array_by_reference(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    if (!values.empty()) references_.push_back({bytes_.size(), std::as_bytes(values)});
  }
  // Room for `more` bytes past the current end: no reallocation (and copy) while they come.
  void reserve(std::size_t more) { bytes_.reserve(bytes_.size() + more); }
  void put(Vec2 v) {
    put(v.x);
    put(v.y);
  }
  void put(Vec3 v) {
    put(v.x);
    put(v.y);
    put(v.z);
  }
  void put(const Box2& b) {
    put(b.min);
    put(b.max);
  }
  void put(const Box3& b) {
    put(b.min);
    put(b.max);
  }
  // An axis as the arguments that rebuild it exactly (GridAxis(lo, hi, cells)).
  void put(const GridAxis& axis) {
    put<std::int32_t>(axis.cells());
    put(axis.cells() > 0 ? axis.lines().front() : 0.0);
    put(axis.cells() > 0 ? axis.lines().back() : 0.0);
  }
  void put(const std::string& s) {
    put<std::uint64_t>(s.size());
    const auto* p = reinterpret_cast<const std::byte*>(s.data());
    bytes_.insert(bytes_.end(), p, p + s.size());
  }

  // The writer's own bytes (the header's room first): the whole file where nothing was put by
  // reference.
  [[nodiscard]] std::vector<std::byte>& bytes() { return bytes_; }
  // Every byte of the file from `from` on (not past the first reference), piece by piece in
  // order, to `to(std::span<const std::byte>)`.
  template <class To>
  void visit(std::size_t from, To to) const {
    const std::span<const std::byte> own(bytes_);
    for (const Reference& r : references_) {
      if (r.at > from) to(own.subspan(from, r.at - from));
      to(r.bytes);
      from = r.at;
    }
    if (own.size() > from) to(own.subspan(from));
  }
  // The file as an image: its pieces view the writer's own buffer, which moves into the image
  // (a moved vector keeps its buffer), and the arrays put by reference.
  [[nodiscard]] IndexImage take_image() {
    IndexImage image;
    visit(0, [&](std::span<const std::byte> piece) { image.pieces_.push_back(piece); });
    image.own_ = std::move(bytes_);
    references_.clear();
    return image;
  }

 private:
  struct Reference {
    std::size_t at;  // where in bytes_ the referenced bytes come
    std::span<const std::byte> bytes;
  };

  std::vector<std::byte> bytes_;
  std::vector<Reference> references_;
};

// An array left in the file's bytes (no copy): elements read one by one, any alignment.
template <class T>
class View {
 public:
  View() = default;
  View(const std::byte* data, std::size_t size) : data_(data), size_(size) {}
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  T operator[](std::size_t i) const {
    T value;
    std::memcpy(&value, data_ + i * sizeof(T), sizeof(T));
    return value;
  }

 private:
  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

// Reads what Writer wrote. The first failure is kept (`error()`); later reads return zeros, so a
// parser reads straight through and checks once at the end of each section.
class Reader {
 public:
  explicit Reader(std::span<const std::byte> bytes) : bytes_(bytes) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value{};
    if (!take(sizeof(T))) return value;
    std::memcpy(&value, bytes_.data() + at_ - sizeof(T), sizeof(T));
    return value;
  }
  template <class T, class Allocator = std::allocator<T>>
  std::vector<T, Allocator> get_array() {
    const auto n = get<std::uint64_t>();
    if (failed_ || n > (bytes_.size() - at_) / sizeof(T)) {
      fail("an array's length runs past the end of the file");
      return {};
    }
    std::vector<T, Allocator> values(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(values.data(), bytes_.data() + at_, values.size() * sizeof(T));
    at_ += values.size() * sizeof(T);
    return values;
  }
  // An array as `get_array` reads it, left in place.
  template <class T>
  View<T> get_view() {
    const auto n = get<std::uint64_t>();
    if (failed_ || n > (bytes_.size() - at_) / sizeof(T)) {
      fail("an array's length runs past the end of the file");
      return {};
    }
    const View<T> view(bytes_.data() + at_, static_cast<std::size_t>(n));
    at_ += view.size() * sizeof(T);
    return view;
  }
  // A count of records that each take at least `min_bytes` of the file.
  std::size_t get_count(std::size_t min_bytes) {
    const auto n = get<std::uint64_t>();
    if (failed_ || n > (bytes_.size() - at_) / min_bytes) {
      fail("a count runs past the end of the file");
      return 0;
    }
    return static_cast<std::size_t>(n);
  }
  double get_double() { return get<double>(); }
  Vec2 get_vec2() {
    const double x = get_double();
    return {x, get_double()};
  }
  Vec3 get_vec3() {
    const double x = get_double(), y = get_double();
    return {x, y, get_double()};
  }
  Box2 get_box2() {
    const Vec2 lo = get_vec2();
    return {lo, get_vec2()};
  }
  Box3 get_box3() {
    const Vec3 lo = get_vec3();
    return {lo, get_vec3()};
  }
  // An axis, checked: 0 cells (the empty default) or 1 .. 2^24 cells over finite lo <= hi.
  GridAxis get_axis() {
    const auto cells = get<std::int32_t>();
    const double lo = get_double(), hi = get_double();
    if (failed_) return {};
    if (cells == 0) return {};
    // Every grid stores at least a byte per cell, so an axis has at most as many cells as the
    // payload has bytes: a crafted count cannot make the reader allocate more than the file.
    if (cells < 0 || cells > (1 << 24) || static_cast<std::size_t>(cells) > bytes_.size() ||
        !(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
      fail("a grid axis is malformed");
      return {};
    }
    return GridAxis(lo, hi, cells);
  }
  std::string get_string() {
    const std::size_t n = get_count(1);
    if (failed_) return {};
    std::string s(reinterpret_cast<const char*>(bytes_.data() + at_), n);
    at_ += n;
    return s;
  }

  // Marks the payload malformed (the first message is kept).
  void fail(const char* message) {
    if (!failed_) message_ = message;
    failed_ = true;
  }
  [[nodiscard]] bool failed() const { return failed_; }
  // The result of the whole read: an error if any read failed or bytes are left over.
  [[nodiscard]] Status finish() {
    if (!failed_ && at_ != bytes_.size()) fail("bytes are left after the index's last section");
    if (failed_) return Error{ErrorKind::parse, std::string("corrupt index file: ") + message_};
    return Ok{};
  }

 private:
  bool take(std::size_t n) {
    if (failed_ || n > bytes_.size() - at_) {
      fail("the file ends inside the index");
      return false;
    }
    at_ += n;
    return true;
  }

  std::span<const std::byte> bytes_;
  std::size_t at_ = 0;
  bool failed_ = false;
  const char* message_ = "";
};

// A triangle's part of a mesh fingerprint (index_file.h: a sum over the triangles), and the
// fingerprint of the sum over `triangles` of them.
[[nodiscard]] std::uint64_t hash_triangle(Vec3 a, Vec3 b, Vec3 c);
[[nodiscard]] std::uint64_t finish_fingerprint(std::uint64_t sum, std::size_t triangles);

// The bytes of a whole index file: `writer`'s payload under the header of `kind` and `source`.
[[nodiscard]] std::vector<std::byte> finish_index(Writer& writer, IndexKind kind,
                                                  std::uint64_t source);
// The same as an image (pieces that refer to the arrays the writer was given by reference).
[[nodiscard]] IndexImage finish_image(Writer& writer, IndexKind kind, std::uint64_t source);

// The error for a sound index file of kind `found` read as one of kind `wanted`.
[[nodiscard]] Error wrong_kind(IndexKind found, IndexKind wanted);

}  // namespace contain::inside::index_bytes
