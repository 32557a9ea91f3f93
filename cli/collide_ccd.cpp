// contain collide: continuous collision (primitives from a query file, moving meshes).

#include "collide_ccd.h"

#include <fmt/format.h>

#include <span>
#include <vector>

#include "common.h"
#include "contain/collide/ccd.h"
#include "contain/collide/moving_mesh_pair.h"
#include "contain/io/ccd_queries.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/number_table.h"
#include "contain/shapes/mesh_validation.h"
#include "progress.h"
#include "timings.h"

namespace contain::cli {
namespace {

// A mesh's motion from --transform-X (a fixed placement) or --from-X and --to-X (both needed).
Result<collide::Motion> motion_option(const std::string& transform, const std::string& from,
                                      const std::string& to, char which) {
  const std::string name(1, which);
  if (from.empty() != to.empty()) {
    return Error{ErrorKind::usage, "--from-" + name + " and --to-" + name +
                                       " go together (placements at t = 0 and 1)"};
  }
  if (!from.empty() && !transform.empty()) {
    return Error{ErrorKind::usage, "--transform-" + name + " and --from-" + name + "/--to-" + name +
                                       " exclude each other"};
  }
  collide::Motion m;
  if (!transform.empty()) {
    auto t = parse_transform(transform, "--transform-" + name);
    if (!t) return t.error();
    m.from = m.to = *t;
  } else if (!from.empty()) {
    auto f = parse_transform(from, "--from-" + name);
    if (!f) return f.error();
    auto t = parse_transform(to, "--to-" + name);
    if (!t) return t.error();
    m.from = *f;
    m.to = *t;
  }
  return m;
}

std::string time_text(double t) {
  return fmt::format("{}", t);  // shortest decimal that reads back as the same double
}

std::string mesh_json(const collide::MeshImpact& m) {
  std::string w;
  switch (m.witness) {
    case collide::MeshImpactWitness::initial:
      w = fmt::format(
          "{{\"kind\":\"initial\",\"discrete\":\"{}\",\"triangle_a\":{},\"triangle_b\":{},"
          "\"vertex\":{}}}",
          collide::to_string(m.initial.witness), m.initial.triangle_a, m.initial.triangle_b,
          m.initial.vertex);
      break;
    case collide::MeshImpactWitness::vertex_a_face_b:
    case collide::MeshImpactWitness::vertex_b_face_a:
      w = fmt::format("{{\"kind\":\"{}\",\"vertex\":{},\"triangle\":{}}}",
                      collide::to_string(m.witness), m.vertex, m.triangle);
      break;
    case collide::MeshImpactWitness::edges:
      w = fmt::format("{{\"kind\":\"edges\",\"edge_a\":[{},{}],\"edge_b\":[{},{}]}}", m.edge_a[0],
                      m.edge_a[1], m.edge_b[0], m.edge_b[1]);
      break;
    case collide::MeshImpactWitness::none:
      w = "null";
      break;
  }
  return fmt::format(
      "{{\"hit\":{},\"time\":{},\"witness\":{},\"node_pairs\":{},\"primitive_tests\":{}}}\n",
      m.hit ? "true" : "false", m.hit ? time_text(m.time) : "null", w, m.node_pairs,
      m.primitive_tests);
}

}  // namespace

int run_ccd_queries(const CcdCliOptions& o) {
  if (!o.a.empty() || !o.b.empty() || has_motion(o) || !o.transform_a.empty() ||
      !o.transform_b.empty()) {
    return report(Error{ErrorKind::usage,
                        "--ccd takes its primitives from --queries FILE, not shapes A and B"});
  }
  if (o.queries.empty()) return report(Error{ErrorKind::usage, "--ccd needs --queries FILE"});
  const bool vertex_face = o.kind == "vertex-face";
  auto read = io::read_ccd_queries(o.queries);
  if (!read) return report(read.error());
  enter_phase(Phase::query);
  const std::vector<collide::CcdQuery>& queries = read->queries;
  std::vector<collide::Impact> impacts(queries.size());
  Progress progress("queries", queries.size(), !o.quiet && stderr_is_terminal());
  progress.run(
      [&](std::size_t begin, std::size_t end) {
        const auto in = std::span<const collide::CcdQuery>(queries).subspan(begin, end - begin);
        const auto out = std::span<collide::Impact>(impacts).subspan(begin, end - begin);
        if (vertex_face) {
          collide::vertex_face_ccd(in, out, {.threads = o.threads});
        } else {
          collide::edge_edge_ccd(in, out, {.threads = o.threads});
        }
      },
      // Chunks of 256 queries: a batch of slow queries (huge and tiny coordinates
      // mixed) still reports progress every second or so.
      256);
  std::string text;
  text.reserve(impacts.size() * 12);
  for (const collide::Impact& i : impacts) {
    if (o.json) {
      text += fmt::format("{{\"hit\":{},\"time\":{},\"stage\":\"{}\"}}\n", i.hit ? "true" : "false",
                          i.hit ? time_text(i.time) : "null", collide::to_string(i.stage));
    } else if (i.hit) {
      text += "hit " + time_text(i.time) + "\n";
    } else {
      text += "miss\n";
    }
  }
  return emit(text, o.out);
}

bool has_motion(const CcdCliOptions& o) {
  return !o.from_a.empty() || !o.to_a.empty() || !o.from_b.empty() || !o.to_b.empty() ||
         !o.motions.empty();
}

int run_moving_meshes(const CcdCliOptions& o) {
  auto motion_a = motion_option(o.transform_a, o.from_a, o.to_a, 'a');
  if (!motion_a) return report(motion_a.error());
  std::vector<collide::Motion> motions;
  if (!o.motions.empty()) {
    if (!o.from_b.empty() || !o.to_b.empty() || !o.transform_b.empty()) {
      return report(Error{ErrorKind::usage,
                          "--motions gives B's placements: --from-b, --to-b and --transform-b "
                          "do not go with it"});
    }
    auto table = io::read_number_table(o.motions, {.columns = {24}});
    if (!table) return report(table.error());
    for (std::size_t r = 0; r < table->rows(); ++r) {
      const std::span<const double> row =
          std::span<const double>(table->values).subspan(r * 24, 24);
      auto from = Transform::from_row_major(row.subspan(0, 12));
      auto to = Transform::from_row_major(row.subspan(12, 12));
      if (!from || !to) {
        Error e = from ? to.error() : from.error();
        e.source = o.motions;
        e.line = table->lines[r];
        return report(e);
      }
      motions.push_back({*from, *to});
    }
  } else {
    auto motion_b = motion_option(o.transform_b, o.from_b, o.to_b, 'b');
    if (!motion_b) return report(motion_b.error());
    motions.push_back(*motion_b);
  }
  auto a = io::read_mesh(o.a);
  if (!a) return report(a.error());
  auto b = io::read_mesh(o.b);
  if (!b) return report(b.error());
  enter_phase(Phase::prepare);
  const collide::MovingMeshPair pair(a->mesh, b->mesh, {.motion_a = *motion_a});
  for (const auto& [solid, name, mesh] : {std::tuple{pair.a_is_solid(), o.a, &a->mesh},
                                          std::tuple{pair.b_is_solid(), o.b, &b->mesh}}) {
    if (solid) continue;
    warn(io::open_mesh_warning(name, validate_mesh(*mesh), io::OpenMeshReading::surface_contact));
  }
  enter_phase(Phase::query);
  std::vector<collide::MeshImpact> impacts(motions.size());
  Progress progress("motions", motions.size(), !o.quiet && stderr_is_terminal());
  progress.run(
      [&](std::size_t begin, std::size_t end) {
        pair.first_contact(std::span<const collide::Motion>(motions).subspan(begin, end - begin),
                           std::span<collide::MeshImpact>(impacts).subspan(begin, end - begin),
                           {.threads = o.threads});
      },
      1);
  std::string text;
  for (const collide::MeshImpact& m : impacts) {
    if (o.json) {
      text += mesh_json(m);
    } else {
      text += m.hit ? "hit " + time_text(m.time) + "\n" : "miss\n";
    }
  }
  return emit(text, o.out);
}

}  // namespace contain::cli
