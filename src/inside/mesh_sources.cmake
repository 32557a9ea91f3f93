# Point in polyhedron (the mesh group of contain::inside): exact ray parity over a prepared
# grid, generalized winding numbers for open meshes.
list(APPEND INSIDE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/winding_number_3d.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fast_winding_number.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_index.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_mesh.cpp)
