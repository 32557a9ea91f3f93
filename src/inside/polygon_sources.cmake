# Point in polygon (ray crossing, winding, angle sum, convex same-side) and the prepared index.
list(APPEND INSIDE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/polygon_kernel.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_polygon.cpp
  ${CMAKE_CURRENT_LIST_DIR}/winding_number.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_polygon_angle_sum.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_convex_polygon.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_index.cpp)
