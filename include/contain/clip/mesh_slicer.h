#pragma once
/// \file
/// A solid prepared once for many planes, sliced a block of planes at a time: the sections of
/// 10^4 planes through 10^6 triangles stream out in bounded memory (`contain slice`), where
/// `slice_mesh` holds them all.

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "contain/clip/slice_mesh.h"
#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::clip {

/// The mesh welded, tested closed, its half-edges paired and its triangles filed under the
/// first of the planes they reach, once; then `slice(begin, end)` gives the sections of
/// values[begin, end), the same `Section`s (bit for bit) as `slice_mesh(mesh, values)` gives
/// there, whatever the blocks and the thread counts.
///
/// The slicer refers to `mesh` (read in place when its vertices are distinct) and keeps a copy
/// of the values: the mesh must outlive it. Blocks of increasing values cost their planes only;
/// a block of values out of order also sweeps (without sectioning) the planes sorted between
/// its least and greatest value.
class MeshSlicer {
 public:
  /// The prepared slicer, or `slice_mesh`'s errors (an open mesh, a value not finite).
  [[nodiscard]] static Result<MeshSlicer> make(const Mesh& mesh, std::span<const double> values,
                                               const SliceOptions& options = {});

  MeshSlicer(MeshSlicer&&) noexcept;
  MeshSlicer& operator=(MeshSlicer&&) noexcept;
  MeshSlicer(const MeshSlicer&) = delete;
  MeshSlicer& operator=(const MeshSlicer&) = delete;
  ~MeshSlicer();

  /// The number of plane values.
  [[nodiscard]] std::size_t size() const;

  /// The sections of values[begin, end) (clamped to `size()`), in that order, on up to
  /// `batch.threads` threads.
  [[nodiscard]] std::vector<Section> slice(std::size_t begin, std::size_t end,
                                           const BatchOptions& batch = {}) const;

 private:
  struct State;
  explicit MeshSlicer(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace contain::clip
