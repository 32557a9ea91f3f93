# Point in polygon: ray crossing and winding, angle sum, convex same-side, the prepared index,
# the GEOS point corpus; with a GMP oracle and a test-only WKT reader.
list(APPEND INSIDE_TESTS
  ${CMAKE_CURRENT_LIST_DIR}/polygon_oracle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_wkt.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_polygon_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_polygon_angle_sum_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_convex_polygon_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/polygon_index_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/point_in_polygon_corpus_test.cpp)
