// A solid prepared once, sliced a block of planes at a time (include/contain/clip/mesh_slicer.h).

#include "contain/clip/mesh_slicer.h"

#include <algorithm>
#include <cmath>
#include <mutex>
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
  // Where the last block left the sweep (`slice::carry_active`): the next block of increasing
  // values starts there rather than rescanning every triangle entered before it. Guarded, as
  // `slice` is const and may be called from several threads.
  std::mutex carry_mutex;
  std::size_t carried_at = 0;
  std::vector<std::size_t> carried;
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
  const std::size_t past = *high + 1;
  // The lock guards only the copy in and the store back: the carries themselves run outside it,
  // so that concurrent callers wait for no one's sweep. Any stored (carried_at, carried) pair is a
  // valid start; a block behind the stored one starts from the first plane.
  std::size_t carried_from = 0;
  std::vector<std::size_t> at_first;
  {
    const std::lock_guard<std::mutex> lock(state_->carry_mutex);
    if (s.carried_at <= first) {
      carried_from = s.carried_at;
      at_first = s.carried;
    }
  }
  slice::carry_active(s.mesh, s.starts, s.sorted, carried_from, first, at_first);
  std::vector<Section> out(end - begin);
  // One plane is a whole 2D boolean: chunks of a single plane are worth a thread.
  parallel_for(past - first, batch, std::size_t{1}, [&](std::size_t from, std::size_t to) {
    std::vector<std::size_t> carried = at_first;
    slice::carry_active(s.mesh, s.starts, s.sorted, first, first + from, carried);
    slice::sweep(s.mesh, s.starts, s.sorted, s.order, first + from, first + to, begin, carried,
                 out);
  });
  slice::carry_active(s.mesh, s.starts, s.sorted, first, past, at_first);
  {
    const std::lock_guard<std::mutex> lock(state_->carry_mutex);
    state_->carried = std::move(at_first);
    state_->carried_at = past;
  }
  return out;
}

}  // namespace contain::clip
