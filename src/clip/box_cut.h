#pragma once
// Regions clipped by a box in one pass (clip_polygon by a box, BoxClipper, tile): the edges that
// can reach the box are cut into pieces by exact decisions, the pieces are linked into chains
// from an entry point on the box's boundary to an exit point, and each exit is joined to the
// next entry counter-clockwise along the boundary, through the corners between them (the
// section's Sutherland-Hodgman result taken apart into valid pieces, all four sides at once).
// Private to clip.
//
// Decisions. Outcodes (Cohen-Sutherland) are comparisons of doubles. Which side an edge crosses
// first, and whether it passes a corner, is the sign of orient2d(p, q, corner). An edge lying on
// a side is kept when the region is on the box's side of it. Crossing points lie on their side
// exactly; their other coordinate is rounded, with a proven bound e on its error.
//
// Where rounding could change the topology the cut gives up (`ok()` false) and the caller uses the
// boolean engine instead, which is exact and valid in every case: two boundary points closer
// than their error bounds (or equal), a crossing within its bound of a corner, an input vertex
// inside the hull of a rounded piece and its exact position (the only way a rounded piece can
// meet another piece that its exact position does not), a ring touching the boundary at a vertex
// where the region lies on both sides of the touching point (a reflex vertex on a side), ends
// that do not alternate (input that is not OGC-valid), or a box whose centre is needed but not
// strictly inside it. None of these occurs for a box in general position.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contain/predicates/sign.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"

namespace contain::clip::detail {

/// Outcode bits: strictly outside each side; kUpper: above the box's centre line (for the parity
/// of the +x ray from the centre, counted on the edges a scan skips).
inline constexpr unsigned kLeft = 1, kRight = 2, kBelow = 4, kTop = 8, kUpper = 16;

inline constexpr std::uint32_t kNoChain = 0xffffffffu;

class BoxCut {
 public:
  /// `box`: finite, min < max on both axes.
  explicit BoxCut(const Box2& box);
  /// Starts over with another box (keeps the buffers).
  void set_box(const Box2& box);

  [[nodiscard]] unsigned code(Vec2 p) const {
    return (p.x < x0_ ? kLeft : 0u) | (p.x > x1_ ? kRight : 0u) | (p.y < y0_ ? kBelow : 0u) |
           (p.y > y1_ ? kTop : 0u) | (p.y > cy_ ? kUpper : 0u);
  }

  /// The edges of `ring` (edge i joins point i to point i + 1, the last one to point 0) that are
  /// not strictly outside one side, in ring order, and the parity of the crossings of the +x ray
  /// from the box's centre with the others. One pass with outcodes.
  void scan(std::span<const Vec2> ring, std::vector<std::uint32_t>& active, bool& parity) const;

  /// Starts a new region (clears everything, keeps the buffers).
  void reset();
  void begin_polygon();
  /// A ring of the current polygon: the shell (hole false) or a hole; `active`: every edge of
  /// the ring that is not strictly outside one side, in ring order (as from scan);
  /// `orientation`: its `predicates::ring_orientation` when known, nullopt to compute it (a ring
  /// of zero area reaching into the box makes the cut give up). False when the ring does not
  /// reach into the box: then the caller gives its parity (add_parity).
  bool add_ring(std::span<const Vec2> ring, std::span<const std::uint32_t> active, bool hole,
                std::optional<Sign> orientation);
  /// The parity of the crossings of the +x ray from the box's centre with a ring that does not
  /// reach into the box (whether the centre is inside it).
  void add_parity(bool odd) { parity_ = parity_ != odd; }
  /// The parity of the crossings of that ray with the `active` edges of a ring that does not
  /// reach into the box (exact: the centre lies on none of them).
  [[nodiscard]] bool active_parity(std::span<const Vec2> ring,
                                   std::span<const std::uint32_t> active) const;
  [[nodiscard]] Vec2 centre() const { return {cx_, cy_}; }
  void end_polygon();

  /// False when a decision was left to the boolean engine (see the file comment).
  [[nodiscard]] bool ok() const { return ok_; }
  /// The result of the region so far; checks the region-wide conditions first (ok() after it).
  [[nodiscard]] MultiPolygon take();

 private:
  // The part of one edge in the closed box, of positive length.
  struct Piece {
    Vec2 a, b;
    double ea = 0.0, eb = 0.0;  // error bounds of a and b along their side (0: exact)
    Vec2 p, q;                  // the whole edge
    std::uint32_t edge = 0;     // its index in the ring
    bool a_vertex = false;      // a is p (b is q)
    bool b_vertex = false;
    bool along = false;  // on a side of the box
  };

  // A chain end on the boundary: side 0 bottom, 1 right, 2 top, 3 left, and the position along it
  // counter-clockwise (key), exact or within err.
  struct End {
    int side;
    double key;
    double err;
    std::uint32_t chain;
    bool exit;
  };

  struct Chain {
    std::uint32_t first, last;  // points_[first .. last)
    std::uint32_t next = kNoChain;
    int corners = 0;    // corners of the walk to the next chain's entry
    int from_side = 0;  // the side of this chain's exit
    bool used = false;
  };

  struct Closed {
    std::uint32_t first, last;  // closed_points_[first .. last)
    bool hole;
  };

  bool cut_edge(Vec2 p, Vec2 q, unsigned cp, unsigned cq, Piece& piece);
  Vec2 cross_x(Vec2 p, Vec2 q, double x, double& err);
  Vec2 cross_y(Vec2 p, Vec2 q, double y, double& err);
  void add_end(Vec2 p, double err, std::uint32_t chain, bool exit);
  [[nodiscard]] int side_of(Vec2 p) const;
  [[nodiscard]] double key_of(Vec2 p, int side) const;
  void trace_polygon();
  [[nodiscard]] bool check_region();
  [[nodiscard]] bool rings_touch();
  [[nodiscard]] bool vertex_in_hull(const Piece& piece) const;
  [[nodiscard]] Ring box_ring() const;

  double x0_, y0_, x1_, y1_, cx_, cy_;
  Vec2 corner_[4];  // corner k starts side k: (x0,y0), (x1,y0), (x1,y1), (x0,y1)
  bool ok_ = true;
  // The current polygon.
  std::vector<Vec2> points_;  // chain points, chain by chain
  std::vector<Chain> chains_;
  std::vector<End> ends_;
  std::vector<Closed> closed_;  // rings wholly in the box (their points in closed_points_)
  std::vector<Vec2> closed_points_;
  bool parity_ = false;  // the centre's parity over the rings that do not reach the box
  // Input vertices in the box, with their ring: two rings of one polygon sharing a vertex (a
  // hole touching its shell, which OGC allows) can pinch the result there.
  struct Tagged {
    Vec2 p;
    std::uint32_t ring;
  };
  std::vector<Tagged> tagged_;
  struct TaggedPiece {
    Vec2 a, b;
    std::uint32_t ring;
  };
  std::vector<TaggedPiece> polygon_pieces_;
  std::uint32_t rings_cut_ = 0;
  // The ring being cut.
  std::vector<Piece> pieces_;
  // The whole region: boundary points and rounded pieces for the checks, and the result.
  std::vector<End> all_ends_;
  std::vector<Piece> rounded_;
  std::vector<Vec2> vertices_;  // input vertices in the box
  MultiPolygon out_;
};

/// The region clipped by the box: the one-pass cut, or the boolean engine where the cut gives
/// up. Valid output (OGC) for OGC-valid input.
[[nodiscard]] MultiPolygon clip_by_box(const MultiPolygon& region, const Box2& box);

/// The box with infinite sides replaced by +-DBL_MAX; empty when it has no interior.
[[nodiscard]] Box2 finite_box(const Box2& box);

/// The region intersected with the box by the boolean engine (the cut's fallback).
[[nodiscard]] MultiPolygon clip_by_box_exactly(const MultiPolygon& region, const Box2& box);

}  // namespace contain::clip::detail
