#include "contain/collide/ccd.h"

#include "collide/ccd_exact.h"
#include "collide/ccd_filter.h"

namespace contain::collide {

namespace {

Impact decide(const CcdQuery& query, detail::PrimitivePair pair) {
  if (const std::optional<Impact> fast = detail::filtered_ccd(query, pair)) return *fast;
  return detail::exact_ccd(query, pair);
}

}  // namespace

Impact vertex_face_ccd(const CcdQuery& query) {
  return decide(query, detail::PrimitivePair::vertex_face);
}

Impact edge_edge_ccd(const CcdQuery& query) {
  return decide(query, detail::PrimitivePair::edge_edge);
}

void vertex_face_ccd(std::span<const CcdQuery> queries, std::span<Impact> out,
                     const BatchOptions& options) {
  batch_map(queries, out, options, 4096, [](const CcdQuery& q) { return vertex_face_ccd(q); });
}

void edge_edge_ccd(std::span<const CcdQuery> queries, std::span<Impact> out,
                   const BatchOptions& options) {
  batch_map(queries, out, options, 4096, [](const CcdQuery& q) { return edge_edge_ccd(q); });
}

}  // namespace contain::collide
