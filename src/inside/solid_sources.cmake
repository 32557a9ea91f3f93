# The solids group of contain::inside (3D point containment and CSG).
list(APPEND INSIDE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/implicit.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_triangle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/convex_polyhedron.cpp
  ${CMAKE_CURRENT_LIST_DIR}/exact_number.cpp
  ${CMAKE_CURRENT_LIST_DIR}/csg_local.cpp
  ${CMAKE_CURRENT_LIST_DIR}/csg.cpp)
