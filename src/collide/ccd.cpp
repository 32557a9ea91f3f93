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
  const std::size_t n = std::min(queries.size(), out.size());
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = vertex_face_ccd(queries[i]);
  });
}

void edge_edge_ccd(std::span<const CcdQuery> queries, std::span<Impact> out,
                   const BatchOptions& options) {
  const std::size_t n = std::min(queries.size(), out.size());
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = edge_edge_ccd(queries[i]);
  });
}

}  // namespace contain::collide
