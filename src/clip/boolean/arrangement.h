#pragma once
// The noded arrangement of the booleans: a planar graph of the input edges of A and B (and of
// open paths), each edge carrying its multiplicity in A and in B, every face its winding numbers.
// Private to polygon_boolean and clip_polylines.

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "clip/boolean/noding.h"
#include "contain/shapes/polygon.h"

namespace contain::clip::detail {

/// What one input segment adds: +1 / 0 per operand along its direction, or an open path piece.
struct SegmentLabel {
  std::int32_t a = 0;
  std::int32_t b = 0;
  bool open = false;
};

/// Input segments of A (label {1, 0}) and B ({0, 1}), zero-length edges left out. Consecutive
/// segments with the same label where one ends and the next starts continue one path.
struct ArrangementInput {
  std::vector<NodingInput> segments;
  std::vector<SegmentLabel> labels;
  /// links[i] != 0: segment i + 1 continues segment i (kept by push(); computed by the
  /// arrangement when its size differs from the segments').
  std::vector<char> links;
  /// Appends the segment a -> b (not of zero length); `continues`: the segment before has the
  /// same label and ends at a (one path).
  void push(Vec2 a, Vec2 b, SegmentLabel label, bool continues) {
    if (!links.empty()) links.back() = continues ? 1 : 0;
    segments.push_back({a, b});
    labels.push_back(label);
    links.push_back(0);
  }
  void reserve(std::size_t n) {
    segments.reserve(n);
    labels.reserve(n);
    links.reserve(n);
  }
  /// Some labels are open (clip_polylines): their pieces are read one by one.
  bool open_paths = false;
  /// Largest coordinate for the noding's hot pixels; 0: that of the segments.
  double magnitude = 0.0;
  void add_rings(std::span<const Ring> rings, SegmentLabel label);
};

class Arrangement {
 public:
  /// Nodes the segments and builds the graph, its faces and their winding numbers. A run of
  /// pieces along a path through points that nothing else meets (Noded::event) is one edge.
  explicit Arrangement(const ArrangementInput& input);

  /// The result region: faces where `keep(w_a, w_b)`, as OGC-valid polygons.
  [[nodiscard]] MultiPolygon extract(const std::function<bool(int, int)>& keep) const;

  /// For each input segment, its pieces in order: a half-edge each (-1 for a piece dropped
  /// because no operand counts it and it is not open).
  [[nodiscard]] std::span<const std::int32_t> pieces_of(std::size_t segment) const {
    return {piece_half_.data() + noded_.first[segment] - segment,
            noded_.first[segment + 1] - noded_.first[segment] - 1};
  }
  /// Winding numbers of the faces left and right of half-edge h.
  [[nodiscard]] int left_a(std::int32_t h) const { return face_a_[face_[h]]; }
  [[nodiscard]] int left_b(std::int32_t h) const { return face_b_[face_[h]]; }
  [[nodiscard]] Vec2 tail_point(std::int32_t h) const { return vertex_[tail(h)]; }
  [[nodiscard]] Vec2 head_point(std::int32_t h) const { return vertex_[head(h)]; }

  std::int64_t crossings = 0;
  std::int64_t rounds = 0;
  std::int64_t edges = 0;
  bool converged = true;

 private:
  // A run of noded pieces from u to v: noded points i0 .. i1 (a joint's two copies are equal
  // neighbours), or a single piece (i0 == kPlain) whose merged copies add up.
  struct Edge {
    std::uint32_t u, v;
    std::int32_t a, b;  // multiplicity along u -> v
    std::uint32_t i0, i1;
    Vec2 du, dv;  // the points after u and before v along the edge
  };
  static constexpr std::uint32_t kPlain = 0xffffffffu;
  // Appends the points of half-edge h from its tail up to (not including) its head.
  void append_points(std::int32_t h, std::vector<Vec2>& out) const;
  [[nodiscard]] std::uint32_t tail(std::int32_t h) const {
    return (h & 1) ? edge_[h >> 1].v : edge_[h >> 1].u;
  }
  [[nodiscard]] std::uint32_t head(std::int32_t h) const {
    return (h & 1) ? edge_[h >> 1].u : edge_[h >> 1].v;
  }
  [[nodiscard]] std::int32_t next(std::int32_t h) const;

  // Stages of the constructor (arrangement.cpp): the graph of the noded pieces ...
  // The vertices (events, path ends, open paths' points), sorted and merged; vid per point.
  [[nodiscard]] std::vector<std::uint32_t> number_vertices(const ArrangementInput& input,
                                                           std::span<const char> links);
  struct Piece;  // a run of one piece, keyed by its vertex pair
  // The runs between vertices: several pieces become an edge at once, single ones are returned.
  [[nodiscard]] std::vector<Piece> collect_runs(const ArrangementInput& input,
                                                std::span<const char> links,
                                                const std::vector<std::uint32_t>& vid);
  // Equal single pieces merge into one edge, their multiplicities added.
  void merge_single_pieces(std::vector<Piece>& pieces, bool any_open);
  // The outgoing half-edges of each vertex, counter-clockwise.
  void sort_half_edges();
  // ... and its faces with their winding numbers (rule clip-faces).
  [[nodiscard]] std::vector<std::int32_t> trace_faces();
  struct Lowest;  // the lowest (x, y) point of a component
  [[nodiscard]] std::vector<Lowest> lowest_points(std::vector<std::uint32_t>& edge_root,
                                                  std::vector<char>& has) const;
  // The face around a component, seen from its lowest point.
  [[nodiscard]] std::int32_t outer_face(const Lowest& low) const;
  // Winding numbers of the lowest point o of component `root` by a ray towards -x; records the
  // face of the component around it.
  void label_outer_face(std::uint32_t root, const Lowest& low, std::int32_t f0,
                        const std::vector<std::uint32_t>& edge_root);
  // Every face of the component from its outer face: w(left) = w(right) + multiplicity.
  void spread_labels(std::int32_t f0, const std::vector<std::int32_t>& face_start,
                     std::vector<char>& done, std::vector<std::int32_t>& queue);
  // Stages of extract (extract.cpp, rule clip-rings): kept faces connected across kept edges
  // form regions; boundary chains become simple rings; rings become polygons.
  [[nodiscard]] std::vector<std::uint32_t> regions(const std::vector<char>& in) const;
  struct Loop;  // a ring of the result, its region and orientation
  [[nodiscard]] std::vector<Loop> trace_rings(const std::vector<char>& in,
                                              const std::vector<std::uint32_t>& region) const;
  [[nodiscard]] Loop make_loop(std::span<const std::int32_t> hs,
                               const std::vector<std::uint32_t>& region) const;
  [[nodiscard]] static MultiPolygon assemble(std::vector<Loop>& loops, std::size_t faces);

  Noded noded_;
  std::vector<Vec2> vertex_;           // sorted by (x, y)
  std::vector<std::uint32_t> origin_;  // first input segment starting at the vertex, or max
  std::vector<Edge> edge_;
  std::vector<std::int32_t> piece_half_;  // per noded piece (chain point but the last)
  std::vector<std::uint32_t> out_first_;  // CSR of outgoing half-edges, counter-clockwise
  std::vector<std::int32_t> out_;
  std::vector<std::uint32_t> pos_;  // position of a half-edge in its tail's list
  std::vector<std::int32_t> face_;  // face left of a half-edge
  std::vector<std::int32_t> face_a_, face_b_;
  // The face around a component and the face of another component that surrounds it: one face.
  std::vector<std::pair<std::int32_t, std::int32_t>> face_links_;
};

}  // namespace contain::clip::detail
