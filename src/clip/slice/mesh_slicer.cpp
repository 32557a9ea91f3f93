// A solid prepared once, sliced a block of planes at a time (include/contain/clip/mesh_slicer.h).

#include "contain/clip/mesh_slicer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "clip/slice/stages.h"

namespace contain::clip {

struct MeshSlicer::State {
  slice::SweepMesh mesh;
  std::vector<std::size_t> order;  // sorted position -> input index
  std::vector<std::size_t> rank;   // input index -> sorted position
  std::vector<double> sorted;
  slice::SweepStarts starts;
};

MeshSlicer::MeshSlicer(std::unique_ptr<State> state) : state_(std::move(state)) {}
MeshSlicer::MeshSlicer(MeshSlicer&&) noexcept = default;
MeshSlicer& MeshSlicer::operator=(MeshSlicer&&) noexcept = default;
MeshSlicer::~MeshSlicer() = default;

Result<MeshSlicer> MeshSlicer::make(const Mesh& mesh, std::span<const double> values,
                                    const SliceOptions& options) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      return Error{ErrorKind::invalid_value,
                   "plane value " + std::to_string(i) + " is not a finite number"};
    }
  }
  auto state = std::make_unique<State>();
  if (Status closed = slice::prepare_closed(mesh, slice::frame_of(options.axis), state->mesh);
      !closed)
    return closed.error();
  state->order.resize(values.size());
  std::iota(state->order.begin(), state->order.end(), std::size_t{0});
  std::stable_sort(state->order.begin(), state->order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  state->sorted.resize(values.size());
  state->rank.resize(values.size());
  for (std::size_t i = 0; i < state->order.size(); ++i) {
    state->sorted[i] = values[state->order[i]];
    state->rank[state->order[i]] = i;
  }
  state->starts = slice::sweep_starts(state->mesh, state->sorted);
  return MeshSlicer(std::move(state));
}

std::size_t MeshSlicer::size() const {
  return state_->order.size();
}

std::vector<Section> MeshSlicer::slice(std::size_t begin, std::size_t end,
                                       const BatchOptions& batch) const {
  end = std::min(end, size());
  if (begin >= end) return {};
  const State& s = *state_;
  // The run of sorted positions holding the block: itself when the values increase.
  const auto [low, high] = std::minmax_element(s.rank.begin() + static_cast<std::ptrdiff_t>(begin),
                                               s.rank.begin() + static_cast<std::ptrdiff_t>(end));
  const std::size_t first = *low;
  std::vector<Section> out(end - begin);
  // One plane is a whole 2D boolean: chunks of a single plane are worth a thread.
  parallel_for(*high + 1 - first, batch, std::size_t{1}, [&](std::size_t from, std::size_t to) {
    slice::sweep(s.mesh, s.starts, s.sorted, s.order, first + from, first + to, begin, out);
  });
  return out;
}

}  // namespace contain::clip
