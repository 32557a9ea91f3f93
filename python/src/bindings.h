#pragma once
/// \file
/// One function per domain adds its classes and functions to the module `contain._contain`.

#include <pybind11/pybind11.h>

namespace contain::python {

namespace py = pybind11;

void bind_io(py::module_& m);            // Mesh, Region, read_mesh, parse_wkt, ...
void bind_inside(py::module_& m);        // MeshIndex, PolygonIndex, point_in_polygon, point_in_mesh
void bind_collide(py::module_& m);       // Contact, MeshPair, collide
void bind_ccd(py::module_& m);           // vertex_face_ccd, edge_edge_ccd, MovingMeshPair, ...
void bind_clip(py::module_& m);          // clip_segments, polygon_boolean
void bind_bound(py::module_& m);         // aabb, bounding_sphere, bounding_circle
void bind_csg(py::module_& m);           // Csg, CsgSolid
void bind_convex(py::module_& m);        // ConvexPolyhedron, ConvexShape, convex_collide
void bind_clip_regions(py::module_& m);  // clip_polygon, clip_mesh, clip_polylines, ...
void bind_mesh_report(py::module_& m);   // validate_mesh, MeshReport, self_intersections, ...
void bind_primitives(py::module_& m);    // tri_tri, tri_tri_2d, pair_search, orient2d, ...
void bind_winding(py::module_& m);   // point_in_triangle, winding_number, FastWindingNumber, ...
void bind_tile(py::module_& m);      // BoxClipper, tile, iter_tiles
void bind_layer(py::module_& m);     // RegionLayer, SolidScene (many shapes at once)
void bind_distance(py::module_& m);  // MeshDistance, RegionDistance, MeshPairDistance
void bind_mesh_boolean(py::module_& m);  // mesh_boolean, repair_solid, MeshBooleanResult
void bind_slice(py::module_& m);         // slice_mesh, shadow, mesh_section
void bind_points(py::module_& m);        // read_points, iter_points, PointChunks

}  // namespace contain::python
