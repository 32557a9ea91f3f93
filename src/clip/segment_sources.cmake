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
# The batch box kernel passes AVX2 lane vectors between always-inlined helpers (box_kernel.h):
# no call crosses the ABI that -Wpsabi warns about.
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/clip_segments.cpp
  PROPERTIES COMPILE_OPTIONS -Wno-psabi)
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/sutherland_hodgman.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_polygon.cpp)
list(APPEND CLIP_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/cap_triangulation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_clip.cpp)
