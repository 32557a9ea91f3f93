# Points and segments (Cohen-Sutherland, Liang-Barsky, Cyrus-Beck, half-space, sphere, batch),
# Sutherland-Hodgman polygons and meshes by half-spaces.
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/clip_point.cpp
  ${CMAKE_CURRENT_LIST_DIR}/box_halfspaces.cpp
  ${CMAKE_CURRENT_LIST_DIR}/segment_halfspace.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cohen_sutherland.cpp
  ${CMAKE_CURRENT_LIST_DIR}/liang_barsky.cpp
  ${CMAKE_CURRENT_LIST_DIR}/convex_functions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cyrus_beck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/segment_sphere.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_segments.cpp)
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/sutherland_hodgman.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_polygon.cpp)
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/cap_triangulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_clip.cpp)
