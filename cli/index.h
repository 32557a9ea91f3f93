#pragma once
// contain index build (a saved index) and contain inside --index (answers from one).

#include <string>

#include "many.h"

namespace contain::cli {

/// The saved index of contain inside --index, and the shape it must have been built from.
struct IndexQuery {
  std::string index;        // --index FILE
  std::string mesh;         // --mesh FILE, empty: not checked (the layer: ManyOptions::layer)
  std::string polygon;      // --polygon FILE, empty: not checked
  bool fill_given = false;  // --fill given: the layer's rule must be it
};

/// contain inside --index FILE [--mesh MESH | --polygon REGION | --layer LAYER]: the saved index
/// answers (a mesh index as --mesh, a polygon index as --polygon, a layer index as --layer with
/// the ids from the file); with a shape, it must have been built from it (exit 3 naming both
/// otherwise).
int run_inside_index(const ManyOptions& query, const IndexQuery& index);

}  // namespace contain::cli
