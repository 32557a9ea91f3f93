#pragma once
// Many shapes at once: contain inside --layer (2D regions with ids) and --scene (3D solids),
// and contain collide --scene (every intersecting pair).

#include <string>
#include <vector>

#include "common.h"
#include "contain/inside/region_layer.h"
#include "contain/inside/solid_scene.h"
#include "contain/io/scene_json.h"

namespace contain::cli {

/// What every form of contain inside takes besides its shapes.
struct PointQuery {
  std::string points = "-";
  std::string out;
  BoundaryPolicy boundary = BoundaryPolicy::report;
  Fill fill = Fill::even_odd;
  int threads = 0;
  bool quiet = false;
};

struct ManyOptions : PointQuery {
  std::string layer;       // --layer FILE or PG:... connection string
  std::string scene;       // --scene FILE (JSON)
  std::string id;          // --id NAME
  std::string layer_name;  // --layer-name NAME
};

/// One line per point: the ids of the regions (solids) holding it, in file order, `ID:on` for a
/// boundary point (folded by --boundary), `-` where none.
int run_layer(const ManyOptions& options);
/// The lines of run_layer from a layer already prepared (or loaded: contain inside --index).
int answer_layer(const inside::RegionLayer& index, const std::vector<std::string>& ids,
                 const ManyOptions& options);
int run_scene_inside(const ManyOptions& options);

/// contain collide --scene: one line per intersecting pair "ID1 ID2" (or a JSON object with
/// the witness), pairs in file order; progress over the candidate pairs on a terminal unless
/// `quiet`.
int run_collide_scene(const std::string& scene, bool json, int threads, bool quiet,
                      const std::string& out);

/// The library's objects of a scene as read (mesh numbers and transforms).
[[nodiscard]] std::vector<inside::SceneObject> scene_objects(const io::Scene& scene);

}  // namespace contain::cli
