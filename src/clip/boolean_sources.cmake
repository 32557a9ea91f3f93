# General polygon booleans and open polylines clipped by polygons (the "booleans" group).
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/boolean_chains.cpp
  ${CMAKE_CURRENT_LIST_DIR}/boolean_noding.cpp
  ${CMAKE_CURRENT_LIST_DIR}/boolean_arrangement.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_boolean.cpp)
list(APPEND CLIP_SOURCES ${CMAKE_CURRENT_LIST_DIR}/polyline_clip.cpp)
