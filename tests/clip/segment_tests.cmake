# Points and segments, Sutherland-Hodgman polygons, meshes by half-spaces; with a GMP oracle.
list(APPEND CLIP_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/segment_oracle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_point_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/segment_halfspace_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/box_segment_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cyrus_beck_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/segment_sphere_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_segments_test.cpp)
list(APPEND CLIP_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/polygon_checks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sutherland_hodgman_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/clip_polygon_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mesh_clip_test.cpp)
